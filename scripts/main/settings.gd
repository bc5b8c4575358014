class_name GameSettings
extends Node
## The player's settings, kept in [code]user://settings.cfg[/code] and applied to the
## [code]Haptics[/code] autoload.
##
## Registered as the [code]Settings[/code] autoload: on start it loads the file and applies
## it (opening the saved device, or the simulated one with a warning when the saved device
## is gone). A missing file means defaults; an unreadable or corrupt one is reported with
## a warning and defaults are used. When the engine starts on a test scene
## ([method is_test_run]) the file is ignored and the defaults are applied. Other instances
## (tests) may use another [member path] and never touch the player's file.
## [codeblock]
## Settings.force_scale = 0.8
## Settings.apply()
## Settings.save_settings()
## [/codeblock]

## Emitted after a value changed through a setter, [method load_settings] or
## [method reset_to_defaults].
signal changed

## Where the autoload keeps the settings.
const DEFAULT_PATH: String = "user://settings.cfg"
## Section of the file holding the haptics settings.
const SECTION: String = "haptics"
## The device every installation has.
const SIMULATED_DEVICE: String = "simulated"
## Control by the haptic device's position (the simulated device follows the mouse).
const CONTROL_DEVICE: StringName = &"device"
## Control by keyboard arrows / WASD / gamepad stick.
const CONTROL_KEYBOARD: StringName = &"keyboard"
## Allowed range of [member force_scale].
const FORCE_SCALE_MIN: float = 0.0
## Allowed range of [member force_scale].
const FORCE_SCALE_MAX: float = 2.0

## File this instance loads from and saves to.
var path: String = DEFAULT_PATH
## Id of the chosen device (a key [code]id[/code] of [code]Haptics.list_devices()[/code]).
var device_id: String = SIMULATED_DEVICE:
	set = set_device_id
## Multiplier on every rendered force, 0–2.
var force_scale: float = 1.0:
	set = set_force_scale
## Whether the continuous force sum is smoothed (impacts stay raw).
var smoothing_enabled: bool = true:
	set = set_smoothing_enabled
## [constant CONTROL_DEVICE] or [constant CONTROL_KEYBOARD].
var control_mode: StringName = CONTROL_DEVICE:
	set = set_control_mode
## Why the last [method load_settings] or [method apply] fell back to something; empty
## when all went well.
var last_warning: String = ""
## Whether [method _ready] loads and applies the file (the autoload does; tests turn it
## off before adding an instance to the tree).
var load_on_ready: bool = true


func _ready() -> void:
	if not load_on_ready:
		return
	if is_test_run():
		# Test scenes get the defaults, whatever the developer last chose in the game.
		reset_to_defaults()
	else:
		load_settings()
	apply()


## Whether the engine was started on a scene under [code]res://tests/[/code] (the test
## runner): the autoload then ignores the player's file so results do not depend on it.
static func is_test_run() -> bool:
	for arg: String in OS.get_cmdline_args():
		if arg.begins_with("res://tests/") and arg.ends_with(".tscn"):
			return true
	return false


## Sets [member device_id]; an empty id means the simulated device.
func set_device_id(value: String) -> void:
	var id: String = value if not value.is_empty() else SIMULATED_DEVICE
	if id != device_id:
		device_id = id
		changed.emit()


## Sets [member force_scale], clamped to 0–2.
func set_force_scale(value: float) -> void:
	var scale: float = clampf(value, FORCE_SCALE_MIN, FORCE_SCALE_MAX)
	if is_nan(value):
		scale = 1.0
	if not is_equal_approx(scale, force_scale):
		force_scale = scale
		changed.emit()


## Sets [member smoothing_enabled].
func set_smoothing_enabled(value: bool) -> void:
	if value != smoothing_enabled:
		smoothing_enabled = value
		changed.emit()


## Sets [member control_mode]; anything but the two known modes means device control.
func set_control_mode(value: StringName) -> void:
	var mode: StringName = CONTROL_KEYBOARD if value == CONTROL_KEYBOARD else CONTROL_DEVICE
	if mode != control_mode:
		control_mode = mode
		changed.emit()


## Restores every value to its default (does not save).
func reset_to_defaults() -> void:
	device_id = SIMULATED_DEVICE
	force_scale = 1.0
	smoothing_enabled = true
	control_mode = CONTROL_DEVICE


## Reads [member path]. A missing file keeps the defaults and returns
## [constant ERR_FILE_NOT_FOUND]; a corrupt one is reported (a warning and
## [member last_warning]), defaults are used and the error is returned. Values of the
## wrong type or out of range fall back to their defaults, or are clamped.
func load_settings() -> Error:
	last_warning = ""
	reset_to_defaults()
	if not FileAccess.file_exists(path):
		return ERR_FILE_NOT_FOUND
	var file: ConfigFile = ConfigFile.new()
	var err: Error = file.load(path)
	if err != OK:
		_warn("Settings file %s is unreadable (%s): using defaults." % [path, error_string(err)])
		return err
	device_id = _read_string(file, "device", SIMULATED_DEVICE)
	force_scale = _read_float(file, "force_scale", 1.0)
	smoothing_enabled = _read_bool(file, "smoothing", true)
	control_mode = StringName(_read_string(file, "control_mode", String(CONTROL_DEVICE)))
	changed.emit()
	return OK


## Writes every value to [member path].
func save_settings() -> Error:
	var file: ConfigFile = ConfigFile.new()
	file.set_value(SECTION, "device", device_id)
	file.set_value(SECTION, "force_scale", force_scale)
	file.set_value(SECTION, "smoothing", smoothing_enabled)
	file.set_value(SECTION, "control_mode", String(control_mode))
	var err: Error = file.save(path)
	if err != OK:
		_warn("Could not save settings to %s: %s." % [path, error_string(err)])
	return err


## Applies the values to the [code]Haptics[/code] autoload: opens [member device_id]
## unless it is already open (falling back to the simulated device with a warning when it
## is gone or fails to open) and sets the force scale, smoothing and control mode. Does
## nothing without the native extension.
func apply() -> void:
	HapticsLink.set_force_scale(force_scale)
	HapticsLink.set_smoothing_enabled(smoothing_enabled)
	HapticsLink.set_control_mode(control_mode)
	if not HapticsLink.is_available():
		return
	if HapticsLink.get_device_id() == device_id:
		return
	if not _device_present(device_id):
		_warn("Haptic device '%s' is gone: using the simulated device." % device_id)
		_open_simulated()
	elif not HapticsLink.open_device(device_id):
		_warn("Haptic device '%s' did not open: using the simulated device." % device_id)
		_open_simulated()


## Every device present ([code]Haptics.list_devices()[/code]); empty without the extension.
func list_devices() -> Array[Dictionary]:
	return HapticsLink.list_devices()


func _open_simulated() -> void:
	if device_id != SIMULATED_DEVICE:
		device_id = SIMULATED_DEVICE
	if HapticsLink.get_device_id() != SIMULATED_DEVICE:
		HapticsLink.open_device(SIMULATED_DEVICE)


func _device_present(id: String) -> bool:
	for device: Dictionary in HapticsLink.list_devices():
		if str(device.get("id", "")) == id:
			return true
	return false


func _warn(message: String) -> void:
	last_warning = message
	push_warning(message)


static func _read_string(file: ConfigFile, key: String, fallback: String) -> String:
	var value: Variant = file.get_value(SECTION, key, fallback)
	if typeof(value) == TYPE_STRING or typeof(value) == TYPE_STRING_NAME:
		return str(value)
	return fallback


static func _read_float(file: ConfigFile, key: String, fallback: float) -> float:
	var value: Variant = file.get_value(SECTION, key, fallback)
	if typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT:
		var number: float = value
		return number
	return fallback


static func _read_bool(file: ConfigFile, key: String, fallback: bool) -> bool:
	var value: Variant = file.get_value(SECTION, key, fallback)
	if typeof(value) == TYPE_BOOL:
		var flag: bool = value
		return flag
	return fallback
