extends TestSuite
## The Settings autoload's persistence: a round trip through a temporary user:// file,
## defaults for a missing, corrupt or out-of-range file, and the fallback to the simulated
## device when the saved one is gone. The player's own settings file is never touched.

var _path: String = ""


func before_each() -> void:
	_path = "user://test_settings_%d.cfg" % Time.get_ticks_usec()


func after_each() -> void:
	if FileAccess.file_exists(_path):
		DirAccess.remove_absolute(_path)
	# Every GameSettings shares the Haptics values: put the test defaults back.
	(get_node(^"/root/Settings") as GameSettings).reload()


func test_the_autoload_is_registered_and_uses_the_documented_file() -> void:
	var settings: GameSettings = get_node_or_null(^"/root/Settings") as GameSettings
	if not assert_not_null(settings, "a Settings autoload of type GameSettings"):
		return
	assert_eq(settings.path, "user://settings.cfg")
	assert_eq(GameSettings.DEFAULT_PATH, "user://settings.cfg")
	assert_true(GameSettings.is_test_run(), "the runner's scene is under res://tests/")
	_assert_defaults(settings)


func test_values_survive_a_save_and_a_reload() -> void:
	var written: GameSettings = _make()
	written.device_id = "hid:0403:cb48"
	written.force_scale = 0.65
	written.smoothing_enabled = false
	written.control_mode = Haptics.CONTROL_KEYBOARD
	written.device_gain_full = true
	written.device_spring_off = false
	assert_eq(written.save_settings(), OK)
	var read: GameSettings = _make()
	assert_eq(read.load_settings(), OK)
	assert_eq(read.device_id, "hid:0403:cb48")
	assert_almost_eq(read.force_scale, 0.65, 1e-6)
	assert_false(read.smoothing_enabled)
	assert_eq(read.control_mode, Haptics.CONTROL_KEYBOARD)
	assert_eq([read.device_gain_full, read.device_spring_off], [true, false])
	assert_eq(read.last_warning, "")


func test_a_missing_file_means_defaults() -> void:
	var settings: GameSettings = _make()
	settings.force_scale = 1.7
	assert_eq(settings.load_settings(), ERR_FILE_NOT_FOUND)
	_assert_defaults(settings)
	assert_eq(settings.last_warning, "", "a first start is not worth a warning")


func test_a_corrupt_file_is_reported_and_defaults_are_used() -> void:
	var file: FileAccess = FileAccess.open(_path, FileAccess.WRITE)
	file.store_string("[haptics\nforce_scale = ((garbage")
	file.close()
	var settings: GameSettings = _make()
	settings.force_scale = 1.7
	expect_error("ConfigFile parse error")
	assert_eq(settings.load_settings(), ERR_PARSE_ERROR)
	_assert_defaults(settings)
	assert_has(settings.last_warning, "unreadable")
	assert_has(settings.last_warning, _path)


func test_wrong_types_and_out_of_range_values_fall_back() -> void:
	var file: ConfigFile = ConfigFile.new()
	file.set_value(GameSettings.SECTION, "device", 42)
	file.set_value(GameSettings.SECTION, "force_scale", 7.5)
	file.set_value(GameSettings.SECTION, "smoothing", "yes please")
	file.set_value(GameSettings.SECTION, "control_mode", "telepathy")
	assert_eq(file.save(_path), OK)
	var settings: GameSettings = _make()
	assert_eq(settings.load_settings(), OK)
	assert_eq(settings.device_id, Haptics.device.get_simulated_id())
	assert_eq(settings.force_scale, Haptics.get_force_scale_range().y, "clamped to 2")
	assert_true(settings.smoothing_enabled)
	assert_eq(settings.control_mode, Haptics.CONTROL_DEVICE)
	assert_false(settings.device_gain_full, "the player's own gain is left alone")
	assert_true(settings.device_spring_off, "the device's centring spring is turned off")


func test_setters_emit_changed_only_on_a_real_change() -> void:
	var settings: GameSettings = _make()
	var count: Array[int] = [0]
	settings.changed.connect(func() -> void: count[0] += 1)
	settings.force_scale = 1.0
	settings.smoothing_enabled = true
	assert_eq(count[0], 0)
	settings.force_scale = 0.5
	settings.control_mode = Haptics.CONTROL_KEYBOARD
	assert_eq(count[0], 2)


func test_a_saved_device_that_is_gone_falls_back_to_the_simulated_one() -> void:
	if not Haptics.is_available():
		skip("needs the haptics extension")
		return
	var settings: GameSettings = _make()
	settings.device_id = "usb:dead:beef:unplugged"
	settings.apply()
	assert_has(settings.last_warning, "usb:dead:beef:unplugged")
	assert_eq(settings.device_id, Haptics.device.get_simulated_id())
	assert_eq(Haptics.device.get_id(), Haptics.device.get_simulated_id())


func test_apply_sets_the_haptics_properties() -> void:
	if not Haptics.is_available():
		skip("needs the haptics extension")
		return
	var settings: GameSettings = _make()
	settings.force_scale = 0.4
	settings.smoothing_enabled = false
	settings.control_mode = Haptics.CONTROL_KEYBOARD
	settings.apply()
	assert_almost_eq(float(Haptics.force_scale), 0.4, 1e-6)
	assert_false(Haptics.smoothing_enabled)
	assert_eq(Haptics.control_mode, &"keyboard")


func test_a_changed_choice_opens_the_device_again_with_it_and_only_then() -> void:
	if not Haptics.is_available():
		skip("needs the haptics extension")
		return
	OS.set_environment("HAPTICS_SCRIPTED_DEVICES", "1")
	var opens: Array[int] = [0]
	var count: Callable = func() -> void: opens[0] += 1
	Haptics.device.changed.connect(count)
	var settings: GameSettings = _make()
	settings.device_id = "scripted:evdev"
	settings.apply()
	assert_eq(Haptics.device.get_id(), "scripted:evdev", settings.last_warning)
	var first: int = opens[0]
	settings.apply()
	assert_eq(opens[0], first, "the same choice: the device is left open as it is")
	settings.device_gain_full = true
	settings.apply()
	assert_eq(opens[0], first + 2, "closed, then opened with the new choice")
	assert_eq(Haptics.device.get_id(), "scripted:evdev", settings.last_warning)
	assert_eq(settings.last_warning, "")
	Haptics.device.changed.disconnect(count)
	OS.unset_environment("HAPTICS_SCRIPTED_DEVICES")


func _make() -> GameSettings:
	var settings: GameSettings = GameSettings.new()
	settings.load_on_ready = false
	settings.path = _path
	add_child_autofree(settings)
	return settings


func _assert_defaults(settings: GameSettings) -> void:
	assert_eq(settings.device_id, Haptics.device.get_simulated_id())
	assert_eq(settings.force_scale, 1.0)
	assert_true(settings.smoothing_enabled)
	assert_eq(settings.control_mode, Haptics.CONTROL_DEVICE)


func test_the_display_settings_survive_a_save_and_refuse_nonsense() -> void:
	var written: GameSettings = _make()
	written.volume = 0.4
	written.fullscreen = true
	written.lab_view = true
	assert_eq(written.save_settings(), OK)
	var read: GameSettings = _make()
	assert_eq(read.load_settings(), OK)
	assert_almost_eq(read.volume, 0.4, 1e-6)
	assert_true(read.fullscreen)
	assert_true(read.lab_view)
	read.volume = NAN
	assert_almost_eq(read.volume, 0.4, 1e-6, "NaN keeps the volume")
	read.volume = 3.0
	assert_almost_eq(read.volume, 1.0, 1e-6, "clamped to full")
	read.reset_to_defaults()
	assert_almost_eq(read.volume, 1.0, 1e-6)
	assert_false(read.fullscreen)
	assert_false(read.lab_view, "the compact HUD by default")


func test_the_autoloads_volume_reaches_the_master_bus() -> void:
	var settings: GameSettings = get_node(^"/root/Settings") as GameSettings
	settings.volume = 0.25
	var bus: int = AudioServer.get_bus_index(&"Master")
	assert_almost_eq(AudioServer.get_bus_volume_linear(bus), 0.25, 1e-3)
	settings.volume = 1.0
	assert_almost_eq(AudioServer.get_bus_volume_linear(bus), 1.0, 1e-3)
