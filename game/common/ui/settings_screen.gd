class_name SettingsScreen
extends Control
## Edits a [GameSettings] (the [code]Settings[/code] autoload unless [member settings] is
## set before the screen enters the tree): device and what the game may change on it, force
## scale, smoothing, control mode,
## volume, fullscreen, the HUD's lab view and the movement keys.
## Changes apply to the haptics at once; [b]Back[/b] (or [code]ui_cancel[/code]) saves
## them when anything changed and emits [signal closed].

## The player left the screen.
signal closed

## Text of the device list's only entry when the extension is missing.
const NO_EXTENSION_TEXT: String = "No haptics extension: playing without force feedback"

## The settings edited; the [code]Settings[/code] autoload when left null.
var settings: GameSettings = null
## Whether to dim what is behind the screen (set when shown over the game).
var dim_background: bool = false

var _device_ids: PackedStringArray = PackedStringArray()
var _devices: Array[HapticDeviceInfo] = []
var _dirty: bool = false
var _refreshing: bool = false
var _keys: KeyBindingRow = KeyBindingRow.new()

@onready var device_option: OptionButton = %DeviceOption
@onready var gain_check: CheckButton = %GainCheck
@onready var spring_check: CheckButton = %SpringCheck
@onready var force_slider: HSlider = %ForceSlider
@onready var smoothing_check: CheckButton = %SmoothingCheck
## Control mode: index 0 device, 1 keyboard.
@onready var control_option: OptionButton = %ControlOption
@onready var volume_slider: HSlider = %VolumeSlider
@onready var fullscreen_check: CheckButton = %FullscreenCheck
@onready var lab_view_check: CheckButton = %LabViewCheck
@onready var defaults_button: Button = %DefaultsButton
## Saves and closes.
@onready var back_button: Button = %BackButton
@onready var _device_info: Label = %DeviceInfo
@onready var _device_own_row: HBoxContainer = %DeviceOwnRow
@onready var _force_value: Label = %ForceValue
@onready var _volume_value: Label = %VolumeValue
@onready var _warning: Label = %Warning
@onready var _dim: ColorRect = %Dim


func _ready() -> void:
	if settings == null:
		settings = get_node_or_null(^"/root/Settings") as GameSettings
	if settings == null:
		settings = GameSettings.new()
		settings.load_on_ready = false
		settings.path = "user://settings_unregistered.cfg"
		add_child(settings)
	_dim.visible = dim_background
	var scale_range: Vector2 = Haptics.get_force_scale_range()
	if is_finite(scale_range.y):
		force_slider.min_value = scale_range.x
		force_slider.max_value = scale_range.y
	control_option.clear()
	control_option.add_item("Haptic device (drag with the mouse to steer)")
	control_option.add_item("Keyboard / gamepad")
	_populate_devices()
	_add_keys_row()
	refresh()
	device_option.item_selected.connect(_on_device_selected)
	gain_check.toggled.connect(_on_gain_toggled)
	spring_check.toggled.connect(_on_spring_toggled)
	force_slider.value_changed.connect(_on_force_changed)
	smoothing_check.toggled.connect(_on_smoothing_toggled)
	control_option.item_selected.connect(_on_control_selected)
	volume_slider.value_changed.connect(_on_volume_changed)
	fullscreen_check.toggled.connect(_on_fullscreen_toggled)
	lab_view_check.toggled.connect(_on_lab_view_toggled)
	defaults_button.pressed.connect(_on_defaults_pressed)
	back_button.pressed.connect(close)
	UiFocus.grab_later(device_option)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		close()


## Saves the settings when they changed and emits [signal closed].
func close() -> void:
	if _dirty:
		settings.save_settings()
		_dirty = false
	closed.emit()


## Shows the current values of [member settings].
func refresh() -> void:
	_refreshing = true
	var index: int = _device_ids.find(settings.device_id)
	if index >= 0:
		device_option.select(index)
	gain_check.button_pressed = settings.device_gain_full
	spring_check.button_pressed = settings.device_spring_off
	force_slider.value = settings.force_scale
	_force_value.text = "%.2f×" % settings.force_scale
	smoothing_check.button_pressed = settings.smoothing_enabled
	control_option.select(1 if settings.control_mode == Haptics.CONTROL_KEYBOARD else 0)
	volume_slider.value = settings.volume
	_volume_value.text = "%d %%" % roundi(settings.volume * 100.0)
	fullscreen_check.button_pressed = settings.fullscreen
	lab_view_check.button_pressed = settings.lab_view
	_keys.show_keys(settings.key_bindings)
	_show_device_info()
	_show_warning(settings.last_warning)
	_refreshing = false


## Label of a device entry: the model (or product), a mark on known haptic devices, and
## "(unavailable)" on haptic devices that cannot be opened now (the info line says why).
static func device_label(device: HapticDeviceInfo) -> String:
	var model: String = device.model
	if model.is_empty():
		model = device.product
	if model.is_empty():
		model = device.id
	var haptic: bool = device.known_haptic
	var unavailable: bool = haptic and not device.openable
	return ("◆ %s" if haptic else "   %s") % model + ("  (unavailable)" if unavailable else "")


func _populate_devices() -> void:
	device_option.clear()
	_device_ids.clear()
	_devices = Haptics.device.list_present()
	for device: HapticDeviceInfo in _devices:
		device_option.add_item(device_label(device))
		_device_ids.append(device.id)
	if _devices.is_empty():
		device_option.add_item(NO_EXTENSION_TEXT)
		device_option.disabled = true


func _show_device_info() -> void:
	var index: int = device_option.selected
	# Only a device of its own has a gain and a centring spring.
	var own: bool = index >= 0 and index < _devices.size()
	_device_own_row.visible = (own and _devices[index].id != Haptics.device.get_simulated_id())
	if index < 0 or index >= _devices.size():
		_device_info.text = "Force feedback needs the native extension (make build)."
		return
	var device: HapticDeviceInfo = _devices[index]
	var parts: PackedStringArray = PackedStringArray()
	if not device.product.is_empty() and device.product != device.model:
		parts.append(device.product)
	parts.append("%s backend" % device.backend)
	var driver: String = device.driver
	parts.append("%s driver" % driver if not driver.is_empty() else "no force-feedback driver")
	if not driver.is_empty() and not device.openable:
		parts.append("cannot be opened: %s" % device.unavailable_reason)
	_device_info.text = "  ·  ".join(parts)


# "Keys" and its buttons, the grid's last row.
func _add_keys_row() -> void:
	var label: Label = Label.new()
	label.text = "Keys"
	var grid: GridContainer = $Center/Panel/Column/Grid
	grid.add_child(label)
	grid.add_child(_keys)
	_keys.key_chosen.connect(_on_key_chosen)


func _on_key_chosen(action: StringName, physical: Key) -> void:
	if physical != KEY_NONE:
		var why: String = settings.bind_key(action, physical)
		if why.is_empty():
			_changed()
		else:
			settings.last_warning = "That key was not taken: %s." % why
	_keys.show_keys(settings.key_bindings)
	_show_warning(settings.last_warning)


func _show_warning(text: String) -> void:
	_warning.text = text
	_warning.visible = not text.is_empty()


func _changed() -> void:
	_dirty = true
	settings.apply()
	_show_warning(settings.last_warning)


func _on_device_selected(index: int) -> void:
	if _refreshing or index < 0 or index >= _device_ids.size():
		return
	settings.last_warning = ""
	settings.device_id = _device_ids[index]
	_changed()
	refresh()


func _on_gain_toggled(on: bool) -> void:
	if not _refreshing:
		settings.device_gain_full = on
		_changed()


func _on_spring_toggled(on: bool) -> void:
	if not _refreshing:
		settings.device_spring_off = on
		_changed()


func _on_force_changed(value: float) -> void:
	_force_value.text = "%.2f×" % value
	if _refreshing:
		return
	settings.force_scale = value
	_changed()


func _on_smoothing_toggled(on: bool) -> void:
	if _refreshing:
		return
	settings.smoothing_enabled = on
	_changed()


func _on_control_selected(index: int) -> void:
	if _refreshing:
		return
	settings.control_mode = Haptics.CONTROL_KEYBOARD if index == 1 else Haptics.CONTROL_DEVICE
	_changed()


func _on_volume_changed(value: float) -> void:
	_volume_value.text = "%d %%" % roundi(value * 100.0)
	if _refreshing:
		return
	settings.volume = value
	_changed()


func _on_fullscreen_toggled(on: bool) -> void:
	if not _refreshing:
		settings.fullscreen = on
		_changed()


func _on_lab_view_toggled(on: bool) -> void:
	if not _refreshing:
		settings.lab_view = on
		_changed()


func _on_defaults_pressed() -> void:
	settings.last_warning = ""
	settings.reset_to_defaults()
	_changed()
	refresh()
