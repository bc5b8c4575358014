extends TestSuite
## The movement keys a player can choose: the project's W A S D by default, any key but the
## ones with their own job, no key for two directions, kept in the settings file, and the
## settings screen's buttons that ask for a key.

const SETTINGS_SCREEN: PackedScene = preload("res://game/common/ui/settings_screen.tscn")


func after_each() -> void:
	# Whatever a test bound, the game's own keys come back.
	var bindings: KeyBindings = KeyBindings.new()
	bindings.apply()


func _keys_of(action: StringName) -> Array[Key]:
	var keys: Array[Key] = []
	for event: InputEvent in InputMap.action_get_events(action):
		if event is InputEventKey:
			keys.append((event as InputEventKey).physical_keycode)
	return keys


func test_the_defaults_are_the_projects_letter_keys() -> void:
	var bindings: KeyBindings = KeyBindings.new()
	assert_eq(bindings.keys[&"move_up"], KEY_W)
	assert_eq(bindings.keys[&"move_down"], KEY_S)
	assert_eq(bindings.keys[&"move_left"], KEY_A)
	assert_eq(bindings.keys[&"move_right"], KEY_D)


func test_a_key_with_its_own_job_or_another_direction_is_refused_and_nothing_changes() -> void:
	var bindings: KeyBindings = KeyBindings.new()
	assert_ne(bindings.bind(&"move_up", KEY_ESCAPE), "", "Escape pauses")
	assert_ne(bindings.bind(&"move_up", KEY_DOWN), "", "the arrows always move")
	assert_has(bindings.bind(&"move_up", KEY_S), "already moves Down")
	assert_ne(bindings.bind(&"jump", KEY_J), "", "not a direction")
	assert_eq(bindings.keys[&"move_up"], KEY_W, "unchanged after four refusals")
	assert_eq(bindings.bind(&"move_up", KEY_I), "")
	assert_eq(bindings.keys[&"move_up"], KEY_I)


func test_a_chosen_key_replaces_the_letter_in_the_input_map_and_the_arrow_stays() -> void:
	var bindings: KeyBindings = KeyBindings.new()
	bindings.bind(&"move_left", KEY_J)
	bindings.apply()
	assert_eq(_keys_of(&"move_left"), [KEY_LEFT, KEY_J] as Array[Key])
	assert_eq(_keys_of(&"move_right"), [KEY_RIGHT, KEY_D] as Array[Key], "the others kept")


func test_keys_survive_the_file_even_swapped_and_a_bad_set_is_refused_whole() -> void:
	var bindings: KeyBindings = KeyBindings.new()
	bindings.keys[&"move_up"] = KEY_S
	bindings.keys[&"move_down"] = KEY_W
	var file: ConfigFile = ConfigFile.new()
	bindings.write(file, "keys")
	var read_back: KeyBindings = KeyBindings.new()
	assert_eq(read_back.read(file, "keys"), "")
	assert_eq(read_back.keys[&"move_up"], KEY_S, "swapped up")
	assert_eq(read_back.keys[&"move_down"], KEY_W, "swapped down")
	file.set_value("keys", "move_left", "A")
	assert_has(read_back.read(file, "keys"), "not a key")
	assert_eq(read_back.keys[&"move_up"], KEY_W, "the defaults, all of them")
	file.set_value("keys", "move_left", KEY_S)
	assert_has(read_back.read(file, "keys"), "already moves")
	assert_eq(read_back.keys, KeyBindings.new().keys)


func test_the_settings_screen_asks_for_a_key_and_escape_cancels() -> void:
	var settings: GameSettings = GameSettings.new()
	settings.load_on_ready = false
	settings.path = "user://test_key_bindings_%d.cfg" % Time.get_ticks_usec()
	add_child_autofree(settings)
	var screen: SettingsScreen = SETTINGS_SCREEN.instantiate() as SettingsScreen
	screen.settings = settings
	add_child_autofree(screen)
	await wait_process_frames(2)
	var row: KeyBindingRow = screen.find_children("*", "KeyBindingRow", true, false)[0]
	var up: Button = row.get_child(0) as Button
	assert_eq(up.text, "Up: W")
	up.pressed.emit()
	assert_eq(up.text, "Up: press a key")
	_press(KEY_ESCAPE)
	assert_eq(up.text, "Up: W", "Escape: nothing changed")
	assert_false(screen.is_queued_for_deletion(), "and the screen stays")
	up.pressed.emit()
	_press(KEY_I)
	assert_eq(up.text, "Up: I")
	assert_eq(settings.key_bindings.keys[&"move_up"], KEY_I)
	up.pressed.emit()
	_press(KEY_D)
	assert_eq(settings.key_bindings.keys[&"move_up"], KEY_I, "D moves right already")
	assert_has(settings.last_warning, "already moves Right")
	screen.close()
	var file: ConfigFile = ConfigFile.new()
	assert_eq(file.load(settings.path), OK, "saved on leaving")
	assert_eq(file.get_value("keys", "move_up"), KEY_I)
	DirAccess.remove_absolute(settings.path)


func _press(physical: Key) -> void:
	var key: InputEventKey = InputEventKey.new()
	key.physical_keycode = physical
	key.pressed = true
	get_viewport().push_input(key)
	key = key.duplicate() as InputEventKey
	key.pressed = false
	get_viewport().push_input(key)
