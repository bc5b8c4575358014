extends Node
## The one door from GDScript to the native [code]HapticsSystem[/code] (registered as the
## [code]Haptics[/code] autoload), and the owner of the game-wide haptic settings: the force
## scale and smoothing (kept in the servo's configuration), the control mode and whether the
## simulated hand follows the user's input.
##
## On start it opens the simulated device and starts the 1 kHz servo thread. The game works
## without the extension: when the native library is missing, [method is_available] is
## false, a warning is printed once, and every query returns a neutral answer (zero
## vectors, empty values, [code]false[/code]). Values cross as typed classes generated from
## their schemas ([code]addons/haptics/values[/code], [code]docs/values.md[/code]); the
## native class itself is named by one script only, the native backend this door loads when
## the library is there, so every other script parses without it.
##
## Besides its own methods the door has two rooms, [member device] (the devices, the open
## one, the simulated hand) and [member servo] (the rendering thread, its statistics and
## telemetry), and a door into each renderer by name ([method renderer]): what only one
## renderer offers (the constraint renderer's walls, Pong's ball) is that renderer's own, in
## its own folder. Vectors are in game axes (x right, y down); forces are in newtons.

## Emitted when the device, the servo state or a setting changes.
signal status_changed

## Class name the extension registers.
const NATIVE_CLASS := &"HapticsSystem"
## The backend that talks to it, loaded only when the class exists.
const NATIVE_BACKEND_PATH := "res://addons/haptics/door/haptics_native_backend.gd"
## The device's input vector drives the player (acceleration control).
const CONTROL_DEVICE := &"device"
## The keyboard or gamepad drives the player.
const CONTROL_KEYBOARD := &"keyboard"
## The project setting naming the four input actions (left, right, up, down) whose strengths
## move the simulated hand; an empty list: none (the mouse still does); an empty name: no
## action in that direction.
const SETTING_HAND_ACTIONS := "haptics/input/hand_actions"
## The project setting naming four input actions (left, right, up, down) the device's input
## vector is fed into as action strengths, for games that read [method Input.get_vector] or
## [method Input.get_axis]; an empty list (the default): none.
const SETTING_FEED_ACTIONS := "haptics/input/feed_actions"
## The project setting for the servo's busy-wait before each deadline, in microseconds
## ([method HapticsServo.start]'s [code]spin_us[/code]: 0 to half a period, or -1, the
## default: the servo's own, [constant HapticServoConstants.DEFAULT_SPIN_NS] under real time
## and none without). More spin, steadier ticks, more of a core; docs/servo-timing.md has the
## measurements.
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
# The keys, buttons, sticks and mouse that move the simulated hand, and the actions fed.
const HapticsInput := preload("res://addons/haptics/door/haptics_input.gd")
const HapticsBackend := preload("res://addons/haptics/door/haptics_backend.gd")

## The player's strength preference, a gain on everything rendered. Kept by the servo
## ([member HapticSafetySettings.force_scale]); finite values are clamped to its range
## ([method get_force_scale_range]), NaN is refused.
var force_scale: float:
	get:
		return servo.get_settings().safety.force_scale if is_available() else _offline_force_scale
	set(value):
		if is_nan(value):
			push_error("Haptics.force_scale: not a number; keeping %s." % force_scale)
			return
		value = clampf(
			value, HapticSafetySettings.FORCE_SCALE_MIN, HapticSafetySettings.FORCE_SCALE_MAX
		)
		if is_available():
			var settings: HapticServoSettings = servo.get_settings()
			settings.safety.force_scale = value
			servo.apply_settings(settings)
		else:
			_offline_force_scale = value
			status_changed.emit()
## Low-pass smoothing of the continuous force (50 Hz frames → 1 kHz output); kept by the
## movement renderer ([member HapticSmoothingSettings.enabled]).
var smoothing_enabled: bool:
	get:
		if not is_available():
			return _offline_smoothing
		return HapticsMovement.of(self).get_settings().smoothing.enabled
	set(value):
		if is_available():
			var movement: HapticsMovement = HapticsMovement.of(self)
			var settings: HapticMovementSettings = movement.get_settings()
			settings.smoothing.enabled = value
			movement.apply_settings(settings)
		else:
			_offline_smoothing = value
			status_changed.emit()
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
## Whether the game is 3D, as its last frame was ([method submit_frame_3d]): the keys then move
## the simulated hand, and the device feeds the actions, on the ground plane.
var game_3d: bool = false
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

var _backend: HapticsBackend = null
var _renderers: Dictionary[StringName, HapticsRenderer] = {}
# The two game-wide settings while there is no servo to keep them (nothing is rendered then).
var _offline_force_scale: float = HapticSafetySettings.new().force_scale
var _offline_smoothing: bool = HapticSmoothingSettings.new().enabled
var _user_input: HapticsInput = HapticsInput.new()


func _init() -> void:
	if ClassDB.class_exists(NATIVE_CLASS):
		_backend = (load(NATIVE_BACKEND_PATH) as GDScript).new()
	else:
		_backend = HapticsBackend.new()
		push_warning(_no_extension_message())
	servo = HapticsServo.new(_backend)
	servo.default_spin_us = _spin_us_setting()
	device = HapticsDevice.new(_backend, servo)
	servo.changed.connect(status_changed.emit)
	device.changed.connect(status_changed.emit)


# Why there is no native server, in words for this platform: the addon ships Linux and
# Windows x86_64 only; elsewhere the engine's own error names no platform we support.
static func _no_extension_message() -> String:
	var platform: String = "%s %s" % [OS.get_name(), Engine.get_architecture_name()]
	if not OS.get_name() in ["Linux", "Windows"] or Engine.get_architecture_name() != "x86_64":
		return (
			"Haptics: %s is not supported (Linux and Windows x86_64 are): " % platform
			+ "playing without force feedback."
		)
	return (
		"Haptics extension not loaded: playing without force feedback. Its library is missing "
		+ "from addons/haptics/bin/ or failed to load (see the error above); from the "
		+ "repository, 'make build' builds it."
	)


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	# Before every other node's physics: the game reads this frame's fed actions.
	process_physics_priority = -1000
	hand_actions = ProjectSettings.get_setting(SETTING_HAND_ACTIONS, DEFAULT_HAND_ACTIONS)
	feed_actions = ProjectSettings.get_setting(SETTING_FEED_ACTIONS, DEFAULT_FEED_ACTIONS)
	if _backend.is_native():
		# Nobody reads telemetry until someone drains it (HapticsServo.drain_telemetry turns
		# it on): a game that never does is not counted telemetry drops.
		var settings: HapticServoSettings = servo.get_settings()
		settings.telemetry.enabled = false
		servo.apply_settings(settings)
	if _backend.is_native() and device.open(device.get_simulated_id()) and not servo.start():
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


func _unhandled_input(event: InputEvent) -> void:
	_user_input.notice_unhandled(event)


func _notification(what: int) -> void:
	if what == NOTIFICATION_APPLICATION_FOCUS_OUT:
		_user_input.release_mouse_stick()


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
		# A 3D game's actions move on the ground: forward (-z) is the "up" action.
		var ground: Vector3 = get_input_vector_3d()
		var push: Vector2 = Vector2(ground.x, ground.z) if game_3d else get_input_vector()
		_user_input.feed(push, control_mode == CONTROL_DEVICE and _backend.is_native())


## Lists the project settings this door reads in the Project Settings dialog, with their
## defaults (the servo's) and ranges; a value the project has set is kept. The addon's editor
## plugin calls it. Without the extension it does nothing: the defaults are the servo's.
static func add_project_settings() -> void:
	if not ClassDB.class_exists(NATIVE_CLASS):
		return
	# -1 is the servo's own choice, which depends on whether the thread gets real time.
	var spin_us: float = HapticsServo.SPIN_US_DEFAULT
	# The slowest servo allows the longest spin; start() refuses more than the rate in use allows.
	var longest_spin_us: float = 0.5e6 / HapticServoConstants.MIN_RATE_HZ
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


## True when the native extension is loaded and answers.
func is_available() -> bool:
	return _backend.is_native()


## The extension's version line, or why there is none.
func get_version() -> String:
	return _backend.version()


## The device's input vector (length ≤ 1); zero without a device.
func get_input_vector() -> Vector2:
	return _backend.input_vector()


## The last servo tick's force, piece by piece, in newtons (game axes): the active renderer's
## components in [member HapticForces.parts] (its force enum names them, e.g.
## [code]HapticMovementFacts.MovementForce.NORMAL[/code]), then what the servo made of them.
func get_forces() -> HapticForces:
	return _backend.forces()


## Hands the servo this physics tick's frame (a [HapticProbe] does, every tick); one the
## servo refuses is reported, naming the field, and the previous frame stays in force.
func submit_frame(frame: HapticFrame) -> bool:
	game_3d = false
	return _backend.submit_frame(frame)


## Rings an impact on the hand (a [HapticProbe] does when a touch begins).
func push_impact(impact: HapticImpact) -> bool:
	return _backend.push_impact(impact)


## A 3D game's [method submit_frame] (a [HapticProbe3D] does, every tick): the game is 3D from
## then on ([member game_3d]).
func submit_frame_3d(frame: HapticFrame3D) -> bool:
	game_3d = true
	return _backend.submit_frame_3d(frame)


## A 3D game's [method push_impact].
func push_impact_3d(impact: HapticImpact3D) -> bool:
	return _backend.push_impact_3d(impact)


## The device's input vector in a 3D game's view axes (x right, y up, z toward the viewer;
## length ≤ 1): a 3-DOF stylus as it is, a 2-axis stick on the ground plane (forward is -z).
func get_input_vector_3d() -> Vector3:
	return _backend.input_vector_3d()


## [method get_forces] in a 3D game's view axes, depth included.
func get_forces_3d() -> HapticForces3D:
	return _backend.forces_3d()


## Makes [param mode] the servo's renderer: [code]&"movement"[/code] (acceleration control,
## the default), [code]&"constraint"[/code] (position control against a maze's walls,
## [HapticsConstraint]) or another the library has ([method renderer]). Unknown names are
## refused with an error.
func set_render_mode(mode: StringName) -> bool:
	if not _backend.is_native():
		return false
	var index: int = _backend.renderer_names().find(mode)
	if index < 0:
		push_error("Haptics.set_render_mode: unknown renderer '%s'." % mode)
		return false
	if get_render_mode() == mode:
		return true
	var accepted: bool = _backend.set_render_mode(index)
	status_changed.emit()
	return accepted


## The current renderer's name ("" without the extension).
func get_render_mode() -> StringName:
	var names: PackedStringArray = _backend.renderer_names()
	var mode: int = _backend.render_mode()
	return StringName(names[mode]) if mode >= 0 and mode < names.size() else &""


## One of the servo's renderers by name ([code]&"movement"[/code], [code]&"constraint"[/code],
## [code]&"pong"[/code]...): make it the active one, send it the values of its own schema,
## read the values it gives. Without the library, or for a name it lacks,
## [method HapticsRenderer.is_available] is false.
func renderer(renderer_name: StringName) -> HapticsRenderer:
	if not _renderers.has(renderer_name):
		var made: HapticsRenderer = HapticsRenderer.new(_backend, renderer_name)
		made.changed.connect(status_changed.emit)
		_renderers[renderer_name] = made
	return _renderers[renderer_name]


## The force scale's allowed range, from its schema.
func get_force_scale_range() -> Vector2:
	return Vector2(HapticSafetySettings.FORCE_SCALE_MIN, HapticSafetySettings.FORCE_SCALE_MAX)


## The mouse stick as the player holds it (for a game to draw); not [member HapticsMouseStick.held]
## while it is let go or the hand does not follow the user.
func get_mouse_stick() -> HapticsMouseStick:
	var stick: HapticsMouseStick = _user_input.mouse_stick(get_viewport())
	stick.held = stick.held and hand_follows_input
	return stick


## Whether [param mode] is a control mode ([constant CONTROL_DEVICE],
## [constant CONTROL_KEYBOARD]).
func is_control_mode(mode: StringName) -> bool:
	return mode == CONTROL_DEVICE or mode == CONTROL_KEYBOARD


## Puts the force scale, smoothing and control mode back to their defaults (their schemas').
func reset_settings() -> void:
	force_scale = HapticSafetySettings.new().force_scale
	smoothing_enabled = HapticSmoothingSettings.new().enabled
	control_mode = CONTROL_DEVICE


# The project's spin for the servo, or the servo's own when it sets none or a value that is
# not a number (reported).
func _spin_us_setting() -> float:
	var value: Variant = ProjectSettings.get_setting(SETTING_SPIN_US, HapticsServo.SPIN_US_DEFAULT)
	if value is float or value is int:
		var spin_us: float = value
		return spin_us
	push_error(
		(
			"Haptics: project setting %s = %s is not a number; using the servo's default."
			% [SETTING_SPIN_US, var_to_str(value)]
		)
	)
	return HapticsServo.SPIN_US_DEFAULT


func _follow_user_input() -> void:
	if hand_follows_input and control_mode == CONTROL_DEVICE and device.is_simulated():
		var target: Vector2 = _user_input.hand_target(get_viewport())
		if game_3d:  # On the ground plane: up pushes the hand forward, into the screen.
			var reach: float = device.get_workspace_radius()
			device.set_hand_target_3d(Vector3(target.x, 0.0, target.y).limit_length(1.0) * reach)
		else:
			device.set_hand_target(target)
