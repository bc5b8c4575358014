extends TestSuite
## The settings screen edits a GameSettings (here one on a temporary file, never the
## player's): the device list with known haptic devices marked, the force scale slider,
## smoothing, control mode, Defaults, and Back saving only when something changed.

const SCREEN_SCENE: PackedScene = preload("res://game/common/ui/settings_screen.tscn")

var _settings: GameSettings = null
var _screen: SettingsScreen = null
var _path: String = ""


func before_each() -> void:
	_path = "user://test_settings_screen_%d.cfg" % Time.get_ticks_usec()
	_settings = GameSettings.new()
	_settings.load_on_ready = false
	_settings.path = _path
	add_child_autofree(_settings)
	_screen = SCREEN_SCENE.instantiate() as SettingsScreen
	_screen.settings = _settings
	add_child_autofree(_screen)
	await wait_process_frames(1)


func after_each() -> void:
	if FileAccess.file_exists(_path):
		DirAccess.remove_absolute(_path)
	# Every GameSettings shares the Haptics values: put the test defaults back.
	(get_node(^"/root/Settings") as GameSettings).reload()


func test_every_device_is_listed_and_known_haptic_ones_are_marked() -> void:
	var devices: Array[HapticDeviceInfo] = Haptics.device.list_present()
	if devices.is_empty():
		assert_eq(_screen.device_option.item_count, 1)
		assert_true(_screen.device_option.disabled, "nothing to choose without the extension")
		return
	assert_eq(_screen.device_option.item_count, devices.size())
	for i: int in devices.size():
		var text: String = _screen.device_option.get_item_text(i)
		assert_has(text, devices[i].model)
		assert_eq(text.begins_with("◆"), devices[i].known_haptic, text)
	assert_eq(_screen.device_option.selected, 0, "the simulated device comes first")


func test_device_labels_fall_back_to_the_product_then_the_id() -> void:
	var gamepad: HapticDeviceInfo = HapticDeviceInfo.new()
	gamepad.id = "hid:1"
	gamepad.product = "Gamepad"
	var label: String = SettingsScreen.device_label(gamepad)
	assert_has(label, "Gamepad")
	assert_false(label.contains("◆"))
	var bare: HapticDeviceInfo = HapticDeviceInfo.new()
	bare.id = "hid:2"
	assert_has(SettingsScreen.device_label(bare), "hid:2")
	var falcon: HapticDeviceInfo = HapticDeviceInfo.new()
	falcon.id = "usb:1-2"
	falcon.model = "Novint Falcon"
	falcon.known_haptic = true
	assert_eq(SettingsScreen.device_label(falcon), "◆ Novint Falcon  (unavailable)", "not openable")
	falcon.openable = true
	assert_eq(SettingsScreen.device_label(falcon), "◆ Novint Falcon")


func test_the_slider_sets_the_force_scale_and_applies_it() -> void:
	_screen.force_slider.value = 0.5
	assert_almost_eq(_settings.force_scale, 0.5, 1e-6)
	var value_label: Label = _screen.find_child("ForceValue", true, false) as Label
	assert_eq(value_label.text, "0.50×")
	if Haptics.is_available():
		assert_almost_eq(float(Haptics.force_scale), 0.5, 1e-6, "applied at once")


func test_smoothing_and_control_mode() -> void:
	_screen.smoothing_check.button_pressed = false
	assert_false(_settings.smoothing_enabled)
	_screen.control_option.select(1)
	_screen.control_option.item_selected.emit(1)
	assert_eq(_settings.control_mode, Haptics.CONTROL_KEYBOARD)
	_screen.control_option.select(0)
	_screen.control_option.item_selected.emit(0)
	assert_eq(_settings.control_mode, Haptics.CONTROL_DEVICE)


func test_the_device_rows_checks_choose_what_the_game_may_change_on_it() -> void:
	assert_false(_screen.gain_check.button_pressed, "the player's gain, by default")
	assert_true(_screen.spring_check.button_pressed, "the centring spring off, by default")
	if Haptics.is_available():
		assert_false(_screen.gain_check.is_visible_in_tree(), "the simulated device has neither")
	_screen.gain_check.button_pressed = true
	_screen.spring_check.button_pressed = false
	var options: HapticDeviceOpenOptions = _settings.open_options()
	assert_eq([options.take_gain, options.spring_off], [true, false])
	_screen.defaults_button.pressed.emit()
	assert_eq(
		[_screen.gain_check.button_pressed, _screen.spring_check.button_pressed], [false, true]
	)


func test_back_saves_the_changes_and_closes() -> void:
	var closed: Array[bool] = [false]
	_screen.closed.connect(func() -> void: closed[0] = true)
	_screen.force_slider.value = 1.5
	_screen.back_button.pressed.emit()
	assert_true(closed[0])
	var reread: GameSettings = GameSettings.new()
	reread.path = _path
	autofree(reread)
	assert_eq(reread.load_settings(), OK)
	assert_almost_eq(reread.force_scale, 1.5, 1e-6)


func test_back_without_changes_writes_nothing() -> void:
	_screen.back_button.pressed.emit()
	assert_false(FileAccess.file_exists(_path))


func test_defaults_restores_every_value_on_screen() -> void:
	_screen.force_slider.value = 0.2
	_screen.smoothing_check.button_pressed = false
	_screen.gain_check.button_pressed = true
	_screen.defaults_button.pressed.emit()
	assert_false(_settings.device_gain_full)
	assert_eq(_settings.force_scale, 1.0)
	assert_true(_settings.smoothing_enabled)
	assert_eq(_screen.force_slider.value, 1.0)
	assert_true(_screen.smoothing_check.button_pressed)
