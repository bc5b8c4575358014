extends Node
## The one door from GDScript to the native [code]HapticsServer[/code] (registered as the
## [code]Haptics[/code] autoload), and the owner of the game-wide haptic settings: the force
## scale and smoothing (kept in the servo's configuration), the control mode and whether the
## simulated hand follows the user's input.
##
## On start it opens the simulated device and starts the 1 kHz servo thread. The game works
## without the extension: when the native library is missing, [method is_available] is
## false, a warning is printed once, and every query returns a neutral answer (zero
## vectors, empty dictionaries, [code]false[/code]). Scripts never name
## [code]HapticsServer[/code] (they must parse without the library): its constants come
## through [method get_constant], its renderers by name ([code]&"constraint"[/code]).
##
## Besides its own methods the door has three rooms: [member device] (the devices, the open
## one, the simulated hand), [member servo] (the rendering thread, its statistics and
## telemetry) and [member pong] (Haptic Battle Pong's renderer: the ball, the paddles, the
## effects). Vectors are in game axes (x right, y down) except in [member pong], which is
## 3D (y up); forces are in newtons.

## Emitted when the device, the servo state or a setting changes.
signal status_changed

## Class name the extension registers.
const SERVER_CLASS := &"HapticsServer"
## The device's input vector drives the player (acceleration control).
const CONTROL_DEVICE := &"device"
## The keyboard or gamepad drives the player.
const CONTROL_KEYBOARD := &"keyboard"
## Force names [method get_forces] reports while the movement or constraint renderer is
## active (each renderer names its own: Pong's are contact, spin and effects).
const FORCE_NAMES: Array[String] = [
	"normal", "friction", "weight", "drag", "inertia", "continuous", "smoothed", "impact", "total"
]
## The project setting naming the four input actions (left, right, up, down) whose strengths
## move the simulated hand; an empty list: none (the mouse still does); an empty name: no
## action in that direction.
const SETTING_HAND_ACTIONS := "haptics/input/hand_actions"
## The project setting naming four input actions (left, right, up, down) the device's input
## vector is fed into as action strengths, for games that read [method Input.get_vector] or
## [method Input.get_axis]; an empty list (the default): none.
const SETTING_FEED_ACTIONS := "haptics/input/feed_actions"
## The project setting for the servo's busy-wait before each deadline, in microseconds
## (HapticsServer.start's [code]spin_us[/code]: 0 to half a period, or -1, the default: the
## servo's own, HapticsServer.DEFAULT_SPIN_US under real time and none without). More spin,
## steadier ticks, more of a core; docs/servo-timing.md has the measurements.
const SETTING_SPIN_US := "haptics/servo/spin_us"
## The hand's actions when the project names none: Godot's own, which every project has
## (arrow keys and a gamepad's d-pad).
const DEFAULT_HAND_ACTIONS: PackedStringArray = ["ui_left", "ui_right", "ui_up", "ui_down"]
## The fed actions when the project names none: none.
const DEFAULT_FEED_ACTIONS: PackedStringArray = []
## The project settings read at start, with their defaults (the addon's plugin lists them in
## Project Settings).
const SETTINGS: Dictionary[String, PackedStringArray] = {
	SETTING_HAND_ACTIONS: DEFAULT_HAND_ACTIONS, SETTING_FEED_ACTIONS: DEFAULT_FEED_ACTIONS
}
# The servo's settings while there is no server to keep them (nothing is rendered then),
# starting from the defaults.
const _OFFLINE_DEFAULTS: Dictionary = {"safety.force_scale": 1.0, "smoothing.enabled": true}
# The keys, buttons, sticks and mouse that move the simulated hand, and the actions fed.
const HapticsInput := preload("haptics_input.gd")

## The player's strength preference, a gain on everything rendered. Kept by the servo;
## finite values are clamped to its range ([method get_force_scale_range]), NaN is refused.
var force_scale: float:
	get:
		return float(_setting("safety", "force_scale"))
	set(value):
		if is_nan(value):
			push_error("Haptics.force_scale: not a number; keeping %s." % force_scale)
			return
		var scale_range: Vector2 = get_force_scale_range()
		_set_setting("safety", "force_scale", clampf(value, scale_range.x, scale_range.y))
## Low-pass smoothing of the continuous force (50 Hz frames → 1 kHz output); kept by the
## servo.
var smoothing_enabled: bool:
	get:
		return bool(_setting("smoothing", "enabled"))
	set(value):
		_set_setting("smoothing", "enabled", value)
## [constant CONTROL_DEVICE] or [constant CONTROL_KEYBOARD]; anything else is refused.
var control_mode: StringName = CONTROL_DEVICE:
	set(value):
		if not is_control_mode(value):
			push_error("Haptics.control_mode: unknown mode '%s' (device or keyboard)" % value)
			return
		control_mode = value
		status_changed.emit()
## When true (the default), the mouse, keyboard and gamepad move the simulated device's
## hand; an autopilot or a test turns it off and moves the hand itself.
var hand_follows_input: bool = true
## The actions (left, right, up, down) that move the simulated hand (from
## [constant SETTING_HAND_ACTIONS]); empty: none. An action the project does not define
## counts as released.
var hand_actions: PackedStringArray:
	get:
		return _user_input.hand_actions
	set(value):
		_user_input.hand_actions = value
## The actions (left, right, up, down) the device's input vector is fed into every physics
## frame while [member control_mode] is "device" (from [constant SETTING_FEED_ACTIONS]);
## empty: none. A game reading [code]Input.get_vector(...)[/code] on them then moves with the
## device. Keys bound to them still work: the stronger of the two wins.
var feed_actions: PackedStringArray:
	get:
		return _user_input.feed_actions
	set(value):
		_user_input.feed_actions = value
## The devices, the open one and the simulated hand.
var device: HapticsDevice = null
## The rendering thread, its statistics and telemetry.
var servo: HapticsServo = null
## Haptic Battle Pong: the ball and paddles simulated in the servo.
var pong: HapticsPong = null

# Typed as Object so that this script parses without the extension.
var _server: Object = null
var _constants: Dictionary[StringName, int] = {}
var _config_fields: Dictionary[String, Dictionary] = {}
var _offline: Dictionary = _OFFLINE_DEFAULTS.duplicate()
var _user_input: HapticsInput = HapticsInput.new()


func _init() -> void:
	if ClassDB.class_exists(SERVER_CLASS):
		_server = ClassDB.instantiate(SERVER_CLASS)
		for constant_name: String in ClassDB.class_get_integer_constant_list(SERVER_CLASS, true):
			_constants[constant_name] = ClassDB.class_get_integer_constant(
				SERVER_CLASS, constant_name
			)
		for field: Dictionary in _server.call(&"get_config_fields"):
			_config_fields["%s.%s" % [field["section"], field["key"]]] = field
	else:
		push_warning(
			(
				"Haptics extension not loaded: playing without force feedback. "
				+ "Build it with 'make build' (see README)."
			)
		)
	servo = HapticsServo.new(_server, get_constant(&"DEFAULT_RATE_HZ"))
	servo.default_spin_us = _spin_us_setting()
	device = HapticsDevice.new(_server, servo)
	# Read without get_constant(): an extension without the Pong renderer is not an error.
	pong = HapticsPong.new(_server, servo, _constants.get(&"RENDER_MODE_PONG", -1))
	servo.changed.connect(status_changed.emit)
	device.changed.connect(status_changed.emit)
	pong.changed.connect(status_changed.emit)


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	# Before every other node's physics: the game reads this frame's fed actions.
	process_physics_priority = -1000
	hand_actions = ProjectSettings.get_setting(SETTING_HAND_ACTIONS, DEFAULT_HAND_ACTIONS)
	feed_actions = ProjectSettings.get_setting(SETTING_FEED_ACTIONS, DEFAULT_FEED_ACTIONS)
	if _server != null:
		# Nobody reads telemetry until someone drains it (HapticsServo.drain_telemetry turns
		# it on): a game that never does is not counted telemetry drops.
		configure("telemetry", {"enabled": false})
	if _server != null and device.open(device.get_simulated_id()) and not servo.start():
		if servo.default_spin_us != HapticsServo.SPIN_US_DEFAULT:
			var refused: float = servo.default_spin_us
			servo.default_spin_us = HapticsServo.SPIN_US_DEFAULT
			push_error(
				(
					"Haptics: project setting %s = %s refused (above); using the servo's default."
					% [SETTING_SPIN_US, refused]
				)
			)
			servo.start()


func _exit_tree() -> void:
	# Zero force is written before the servo thread is joined (the core guarantees it).
	servo.stop()


func _input(event: InputEvent) -> void:
	_user_input.notice(event)


func _process(delta: float) -> void:
	device.poll_reconnect(delta)
	# Fed after the frame's physics too: a RigidBody2D's _integrate_forces runs first in the
	# next tick, and Input.is_action_just_pressed counts a press made within a tick later.
	_follow_user_input_and_feed()


func _physics_process(_delta: float) -> void:
	_follow_user_input_and_feed()


func _follow_user_input_and_feed() -> void:
	_follow_user_input()
	if not feed_actions.is_empty():
		_user_input.feed(get_input_vector(), control_mode == CONTROL_DEVICE and _server != null)


## Lists the project settings this door reads in the Project Settings dialog, with their
## defaults (the servo's) and ranges; a value the project has set is kept. The addon's editor
## plugin calls it. Without the extension it does nothing: the defaults are the servo's.
static func add_project_settings() -> void:
	if not ClassDB.class_exists(SERVER_CLASS):
		return
	# -1 is the servo's own choice, which depends on whether the thread gets real time.
	var spin_us: float = HapticsServo.SPIN_US_DEFAULT
	# The slowest servo allows the longest spin; start() refuses more than the rate in use allows.
	var longest_spin_us: float = (
		0.5e6 / ClassDB.class_get_integer_constant(SERVER_CLASS, &"MIN_RATE_HZ")
	)
	if not ProjectSettings.has_setting(SETTING_SPIN_US):
		ProjectSettings.set_setting(SETTING_SPIN_US, spin_us)
	ProjectSettings.set_initial_value(SETTING_SPIN_US, spin_us)
	var info: Dictionary = {
		"name": SETTING_SPIN_US,
		"type": TYPE_FLOAT,
		"hint": PROPERTY_HINT_RANGE,
		"hint_string": "%d,%d,1,suffix:µs" % [spin_us, longest_spin_us],
	}
	ProjectSettings.add_property_info(info)


## True when the native extension is loaded and its server exists.
func is_available() -> bool:
	return _server != null


## The native server itself, for a [HapticProbe]; game code uses this door.
func get_server() -> Object:
	return _server


## A [code]HapticsServer[/code] integer constant by name ([code]&"MAX_CONTACTS"[/code],
## [code]&"TELEMETRY_FLAG_CONTACT"[/code]…); 0 without the extension.
func get_constant(constant_name: StringName) -> int:
	if _server != null and not _constants.has(constant_name):
		push_error("Haptics: HapticsServer has no constant '%s'." % constant_name)
	return _constants.get(constant_name, 0)


## The extension's version line, or why there is none.
func get_version() -> String:
	return str(_server.call(&"get_version")) if _server != null else "haptics extension not loaded"


## The device's input vector (length ≤ 1); zero without a device.
func get_input_vector() -> Vector2:
	return _server.call(&"get_input_vector") if _server != null else Vector2.ZERO


## Rendered force components in newtons, one [Vector2] per name in [constant FORCE_NAMES].
func get_forces() -> Dictionary:
	if _server != null:
		return _server.call(&"get_forces")
	var zeros: Dictionary = {}
	for force_name: String in FORCE_NAMES:
		zeros[force_name] = Vector2.ZERO
	return zeros


## One component of a [method get_forces] result (zero when absent).
func force_of(forces: Dictionary, component: String) -> Vector2:
	var value: Variant = forces.get(component, Vector2.ZERO)
	return value if value is Vector2 else Vector2.ZERO


## The renderer: [code]&"movement"[/code] (acceleration control, the default) or
## [code]&"constraint"[/code] (position control against walls set with
## [method set_constraint_geometry]). Unknown names are refused with an error.
func set_render_mode(mode: StringName) -> bool:
	var constant_name: StringName = "RENDER_MODE_" + mode.to_upper()
	if _server == null:
		return false
	if not _constants.has(constant_name):
		push_error("Haptics.set_render_mode: unknown renderer '%s'." % mode)
		return false
	if get_render_mode() == mode:
		return true
	var accepted: bool = _server.call(&"set_render_mode", _constants[constant_name])
	status_changed.emit()
	return accepted


## The current renderer's name ("" without the extension).
func get_render_mode() -> StringName:
	if _server == null:
		return &""
	var mode: int = _server.call(&"get_render_mode")
	for constant_name: StringName in _constants:
		if constant_name.begins_with("RENDER_MODE_") and _constants[constant_name] == mode:
			return StringName(constant_name.trim_prefix("RENDER_MODE_").to_lower())
	return &""


## Walls for the constraint renderer as point pairs in maze units (pixels), and how the
## maze maps onto the workspace.
func set_constraint_geometry(segments: PackedVector2Array, mapping: HapticMazeMapping) -> bool:
	return (
		_server != null
		and _server.call(&"set_constraint_geometry", segments, mapping.to_dictionary())
	)


## The constraint proxy: position (maze units), goal, constraints, placed, updates; empty
## without the extension.
func get_proxy_state() -> Dictionary:
	return _server.call(&"get_proxy_state") if _server != null else {}


## Changes settings of one section (HapticsServer.get_config_fields lists them); only the
## keys given change. Refused settings are reported and change nothing.
func configure(section: String, values: Dictionary) -> bool:
	if _server == null:
		return false
	var accepted: bool = _server.call(&"set_config", section, values)
	status_changed.emit()
	return accepted


## Every section of the servo's configuration with every key; empty without the extension.
func get_config() -> Dictionary:
	return _server.call(&"get_config") if _server != null else {}


## The name of the value a choice setting has now, e.g. [code]"per_contact"[/code] for
## [code]get_choice("force_model", "contact_model")[/code]; empty without the extension.
func get_choice(section: String, key: String) -> String:
	if _server == null:
		return ""
	var field: Dictionary = _config_fields.get("%s.%s" % [section, key], {})
	var choices: Array = field.get("choices", [])
	var value: int = int(_setting(section, key))
	if value < 0 or value >= choices.size():
		push_error("Haptics.get_choice: %s.%s is not a choice setting." % [section, key])
		return ""
	return str(choices[value])


## The force scale's allowed range (from the servo's field table; without the extension
## anything finite and not negative).
func get_force_scale_range() -> Vector2:
	var field: Dictionary = _config_fields.get("safety.force_scale", {})
	return Vector2(field.get("min", 0.0), field.get("max", INF))


## Whether [param mode] is a control mode ([constant CONTROL_DEVICE],
## [constant CONTROL_KEYBOARD]).
func is_control_mode(mode: StringName) -> bool:
	return mode == CONTROL_DEVICE or mode == CONTROL_KEYBOARD


## Puts the force scale, smoothing and control mode back to their defaults (the servo's
## defaults for the first two).
func reset_settings() -> void:
	force_scale = float(_default("safety.force_scale"))
	smoothing_enabled = bool(_default("smoothing.enabled"))
	control_mode = CONTROL_DEVICE


func _setting(section: String, key: String) -> Variant:
	if _server == null:
		return _offline["%s.%s" % [section, key]]
	var config: Dictionary = _server.call(&"get_config")
	return config[section][key]


func _set_setting(section: String, key: String, value: Variant) -> void:
	if _server != null:
		configure(section, {key: value})
	else:
		_offline["%s.%s" % [section, key]] = value
		status_changed.emit()


func _default(field_name: String) -> Variant:
	return (
		_config_fields[field_name]["default"] if _server != null else _OFFLINE_DEFAULTS[field_name]
	)


# The project's spin for the servo, or the servo's own when it sets none or a value that is
# not a number (reported).
func _spin_us_setting() -> float:
	var value: Variant = ProjectSettings.get_setting(SETTING_SPIN_US, HapticsServo.SPIN_US_DEFAULT)
	if value is float or value is int:
		return float(value)
	push_error(
		(
			"Haptics: project setting %s = %s is not a number; using the servo's default."
			% [SETTING_SPIN_US, var_to_str(value)]
		)
	)
	return HapticsServo.SPIN_US_DEFAULT


func _follow_user_input() -> void:
	if hand_follows_input and control_mode == CONTROL_DEVICE and device.is_simulated():
		device.set_hand_target(_user_input.hand_target(get_viewport()))
