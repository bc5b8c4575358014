class_name GameSettings
extends Node
## Keeps the player's settings in [code]user://settings.cfg[/code]: the chosen device and what
## the game may change on it (its own gain and centring spring), the
## [code]Haptics[/code] autoload's force scale, smoothing and control mode, and the
## display's: volume, fullscreen and the HUD's lab view; and the player's movement keys
## ([KeyBindings]).
##
## The values themselves, their defaults and their validation belong to [code]Haptics[/code]:
## [member force_scale], [member smoothing_enabled] and [member control_mode] read and write
## it, so every instance of this class sees the same values and only the file differs. The
## device choice is this class's own: it is what the player picked, which may be gone.
##
## Registered as the [code]Settings[/code] autoload: on start it loads the file and applies
## it (opening the saved device, or the simulated one with a warning when the saved device
## is gone). A missing file means defaults; an unreadable or corrupt one is reported with a
## warning and defaults are used. When the engine starts on a test scene
## ([method is_test_run]) the file is ignored and the defaults are applied. Other instances
## (tests) may use another [member path] and never touch the player's file.
## [codeblock]
## Settings.force_scale = 0.8
## Settings.save_settings()
## [/codeblock]

## Emitted after a value changed through a setter, [method load_settings] or
## [method reset_to_defaults].
signal changed

## Where the autoload keeps the settings.
const DEFAULT_PATH: String = "user://settings.cfg"
## Section of the file holding the haptics settings.
const SECTION: String = "haptics"
## Section of the file holding the display settings.
const DISPLAY_SECTION: String = "display"
## Section of the file holding the movement keys.
const KEYS_SECTION: String = "keys"

## File this instance loads from and saves to.
var path: String = DEFAULT_PATH
## Id of the chosen device (a key [code]id[/code] of [code]Haptics.device.list_present()[/code]);
## empty means the simulated device.
var device_id: String = "":
	set = set_device_id
## Whether opening the device sets its own gain to full
## ([member HapticDeviceOpenOptions.take_gain]); off, the player's gain scales what is felt.
var device_gain_full: bool = false:
	set(value):
		if value != device_gain_full:
			device_gain_full = value
			changed.emit()
## Whether opening the device turns its own centring spring off
## ([member HapticDeviceOpenOptions.spring_off]).
var device_spring_off: bool = true:
	set(value):
		if value != device_spring_off:
			device_spring_off = value
			changed.emit()
## [code]Haptics.force_scale[/code].
var force_scale: float:
	get:
		return Haptics.force_scale
	set(value):
		_change(func() -> void: Haptics.force_scale = value)
## [code]Haptics.smoothing_enabled[/code].
var smoothing_enabled: bool:
	get:
		return Haptics.smoothing_enabled
	set(value):
		_change(func() -> void: Haptics.smoothing_enabled = value)
## [code]Haptics.control_mode[/code]; anything but a known mode means device control.
var control_mode: StringName:
	get:
		return Haptics.control_mode
	set(value):
		var mode: StringName = value if Haptics.is_control_mode(value) else Haptics.CONTROL_DEVICE
		_change(func() -> void: Haptics.control_mode = mode)
## The master volume, 0 (silent) to 1 (full), applied to the audio's master bus.
var volume: float = 1.0:
	set(value):
		var clamped: float = clampf(value, 0.0, 1.0) if is_finite(value) else volume
		if clamped != volume:
			volume = clamped
			_apply_display()
			changed.emit()
## Whether the game fills the screen.
var fullscreen: bool = false:
	set(value):
		if value != fullscreen:
			fullscreen = value
			_apply_display()
			changed.emit()
## Whether the side-scroller's HUD opens in its lab view (forces, plot, device); the H key
## switches it during play too.
var lab_view: bool = false:
	set(value):
		if value != lab_view:
			lab_view = value
			changed.emit()
## The movement keys; change them with [method bind_key].
var key_bindings: KeyBindings = KeyBindings.new()
## Why the last [method load_settings] or [method apply] fell back to something; empty
## when all went well.
var last_warning: String = ""
## Whether [method _ready] loads and applies the file (the autoload does; tests turn it
## off before adding an instance to the tree).
var load_on_ready: bool = true

# The device this instance opened and the options it opened it with (their bytes): options
# changed since are applied by opening it again.
var _opened_id: String = ""
var _opened_options: PackedByteArray = PackedByteArray()


func _init() -> void:
	device_id = Haptics.device.get_simulated_id()


func _ready() -> void:
	if load_on_ready:
		reload()


## Loads the settings (the defaults in a test run, see [method is_test_run]; else
## [member path]) and applies them.
func reload() -> void:
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
	var id: String = value if not value.is_empty() else Haptics.device.get_simulated_id()
	if id != device_id:
		device_id = id
		changed.emit()


## Restores every value to its default (does not save).
func reset_to_defaults() -> void:
	device_id = Haptics.device.get_simulated_id()
	var options: HapticDeviceOpenOptions = HapticDeviceOpenOptions.new()
	device_gain_full = options.take_gain
	device_spring_off = options.spring_off
	volume = 1.0
	fullscreen = false
	lab_view = false
	key_bindings.reset()
	_apply_keys()
	_change(Haptics.reset_settings)


## Reads [member path]. A missing file keeps the defaults and returns
## [constant ERR_FILE_NOT_FOUND]; a corrupt one is reported (a warning and
## [member last_warning]), defaults are used and the error is returned. Values of the
## wrong type fall back to their defaults; out-of-range ones are clamped by
## [code]Haptics[/code].
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
	device_id = _read(file, "device", TYPE_STRING, device_id)
	force_scale = _read(file, "force_scale", TYPE_FLOAT, force_scale)
	smoothing_enabled = _read(file, "smoothing", TYPE_BOOL, smoothing_enabled)
	device_gain_full = _read(file, "device_gain_full", TYPE_BOOL, device_gain_full)
	device_spring_off = _read(file, "device_spring_off", TYPE_BOOL, device_spring_off)
	var mode: String = _read(file, "control_mode", TYPE_STRING, String(control_mode))
	control_mode = StringName(mode)
	volume = _read(file, "volume", TYPE_FLOAT, volume, DISPLAY_SECTION)
	fullscreen = _read(file, "fullscreen", TYPE_BOOL, fullscreen, DISPLAY_SECTION)
	lab_view = _read(file, "lab_view", TYPE_BOOL, lab_view, DISPLAY_SECTION)
	var refused: String = key_bindings.read(file, KEYS_SECTION)
	if not refused.is_empty():
		_warn("Saved keys not used (%s): the default keys apply." % refused)
	_apply_keys()
	changed.emit()
	return OK


## Writes every value to [member path].
func save_settings() -> Error:
	var file: ConfigFile = ConfigFile.new()
	file.set_value(SECTION, "device", device_id)
	file.set_value(SECTION, "force_scale", force_scale)
	file.set_value(SECTION, "smoothing", smoothing_enabled)
	file.set_value(SECTION, "device_gain_full", device_gain_full)
	file.set_value(SECTION, "device_spring_off", device_spring_off)
	file.set_value(SECTION, "control_mode", String(control_mode))
	file.set_value(DISPLAY_SECTION, "volume", volume)
	file.set_value(DISPLAY_SECTION, "fullscreen", fullscreen)
	file.set_value(DISPLAY_SECTION, "lab_view", lab_view)
	key_bindings.write(file, KEYS_SECTION)
	var err: Error = file.save(path)
	if err != OK:
		_warn("Could not save settings to %s: %s." % [path, error_string(err)])
	return err


## Opens [member device_id] with [method open_options] unless it is already open so,
## falling back to the simulated device with a warning when it is gone or fails to open.
## Does nothing without the native extension.
func apply() -> void:
	if not Haptics.is_available():
		return
	var options: HapticDeviceOpenOptions = open_options()
	var open_id: String = Haptics.device.get_id()
	if open_id == device_id:
		if open_id != _opened_id or options.encode() == _opened_options:
			return  # Opened elsewhere, or so already: nothing of ours to change.
		# A device is not opened twice at once (a Falcon's USB interface is claimed once).
		Haptics.device.close()
	var listed: HapticDeviceInfo = _listed(device_id)
	if listed == null:
		_warn("Haptic device '%s' is gone: using the simulated device." % device_id)
		_open_simulated()
	elif not listed.openable:
		_warn(
			(
				"Haptic device '%s' cannot be opened: %s. Using the simulated device."
				% [device_id, listed.unavailable_reason]
			)
		)
		_open_simulated()
	elif not Haptics.device.open(device_id, options):
		_warn("Haptic device '%s' did not open: using the simulated device." % device_id)
		_open_simulated()
	else:
		_opened_id = device_id
		_opened_options = options.encode()


## What opening the device may change on it, as the player chose.
func open_options() -> HapticDeviceOpenOptions:
	var options: HapticDeviceOpenOptions = HapticDeviceOpenOptions.new()
	options.take_gain = device_gain_full
	options.spring_off = device_spring_off
	return options


## Moves [param action] (one of [constant KeyBindings.ACTIONS]) to the key at
## [param physical]; returns why not (nothing changes then), or "".
func bind_key(action: StringName, physical: Key) -> String:
	var why: String = key_bindings.bind(action, physical)
	if why.is_empty():
		_apply_keys()
		changed.emit()
	return why


# Runs a change of the Haptics settings and emits `changed` if it changed anything.
func _change(change: Callable) -> void:
	var before: Array = [force_scale, smoothing_enabled, control_mode]
	change.call()
	if [force_scale, smoothing_enabled, control_mode] != before:
		changed.emit()


# Volume and window mode take effect at once for the autoload's settings (other instances,
# the tests', turn load_on_ready off); a headless run has no window to change.
func _apply_display() -> void:
	if not (load_on_ready and is_inside_tree()):
		return
	var bus: int = AudioServer.get_bus_index(&"Master")
	if bus >= 0:
		AudioServer.set_bus_volume_linear(bus, volume)
	if DisplayServer.get_name() == "headless":
		return
	var window: Window = get_tree().root
	var wanted: Window.Mode = Window.MODE_FULLSCREEN if fullscreen else Window.MODE_WINDOWED
	if window.mode != wanted and not (window.mode == Window.MODE_MAXIMIZED and not fullscreen):
		window.mode = wanted


# The keys go into the input map for the autoload's settings only (tests' instances leave
# the game's keys alone).
func _apply_keys() -> void:
	if load_on_ready and is_inside_tree():
		key_bindings.apply()


func _open_simulated() -> void:
	var simulated: String = Haptics.device.get_simulated_id()
	device_id = simulated
	if Haptics.device.get_id() != simulated:
		Haptics.device.open(simulated, open_options())


func _listed(id: String) -> HapticDeviceInfo:
	for device: HapticDeviceInfo in Haptics.device.list_present():
		if device.id == id:
			return device
	return null


func _warn(message: String) -> void:
	last_warning = message
	push_warning(message)


# The file's value of [param key] in [param section] if it has [param type] (an int counts
# as a float), else [param fallback].
static func _read(
	file: ConfigFile, key: String, type: Variant.Type, fallback: Variant, section: String = SECTION
) -> Variant:
	var value: Variant = file.get_value(section, key, fallback)
	var found: int = typeof(value)
	if found == type or (type == TYPE_FLOAT and found == TYPE_INT):
		return value
	if type == TYPE_STRING and found == TYPE_STRING_NAME:
		return str(value)
	return fallback
