extends Node
## Autoload that owns the native [code]HapticsServer[/code] and the game-wide haptic
## settings.
##
## On start it opens the simulated device and starts the 1 kHz servo thread. The game works
## without the extension: when the native library is missing, [method is_available] is
## false, a warning is printed once, and every query returns a neutral answer (zero
## vectors, empty dictionaries) instead of failing to parse or crash.
##
## Vectors are in game axes (x right, y down). "Normalised" positions are fractions of the
## device's workspace radius, each axis in [-1, 1].

## Emitted when the device, the servo state or a setting changes.
signal status_changed

## Class name the extension registers.
const SERVER_CLASS := &"HapticsServer"
## Device opened at start and used when a requested device cannot be opened.
const DEFAULT_DEVICE := "simulated"
## Control modes: the device's input vector drives the player, or the keyboard/gamepad.
const CONTROL_DEVICE := &"device"
## See [constant CONTROL_DEVICE].
const CONTROL_KEYBOARD := &"keyboard"
## Force names reported by [method get_forces].
const FORCE_NAMES: Array[String] = [
	"normal", "friction", "weight", "drag", "inertia", "continuous", "smoothed", "impact", "total"
]

## Multiplies every force the game asks for (0 = off, 1 = as designed, up to 2).
var force_scale: float = 1.0:
	set = set_force_scale
## Low-pass smoothing of the continuous force (50 Hz frames → 1 kHz output).
var smoothing_enabled: bool = true:
	set = set_smoothing_enabled
## [constant CONTROL_DEVICE] or [constant CONTROL_KEYBOARD].
var control_mode: StringName = CONTROL_DEVICE:
	set = set_control_mode
## When true (the default), the mouse, keyboard and gamepad move the simulated device's
## hand; an autopilot or a test turns it off and calls [method set_hand_target] itself.
var hand_follows_input: bool = true

## The native server, or [code]null[/code] when the extension is not loaded. Typed as
## [RefCounted] so that this script parses even without the extension.
var server: RefCounted = null

var _mouse_seen: bool = false


func _init() -> void:
	if ClassDB.class_exists(SERVER_CLASS):
		server = ClassDB.instantiate(SERVER_CLASS)
	else:
		push_warning(
			(
				"Haptics extension not loaded: playing without force feedback. "
				+ "Build it with 'make build' (see README)."
			)
		)


func _ready() -> void:
	process_mode = Node.PROCESS_MODE_ALWAYS
	if server != null and open_device(DEFAULT_DEVICE):
		start()


func _exit_tree() -> void:
	# Zero force is written before the servo thread is joined (the core guarantees it).
	if server != null:
		server.call(&"stop")


func _input(event: InputEvent) -> void:
	if event is InputEventMouseMotion:
		_mouse_seen = true


func _process(_delta: float) -> void:
	if hand_follows_input and control_mode == CONTROL_DEVICE and is_simulated():
		set_hand_target(_hand_from_user_input())


## True when the native extension is loaded and its server exists.
func is_available() -> bool:
	return server != null


## Every device present (the simulated one first), each a [Dictionary]; empty without the
## extension.
func list_devices() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if server != null:
		var entries: Array = server.call(&"list_devices")
		out.assign(entries)
	return out


## Opens the device with this id and keeps rendering if it was. On failure the current
## device stays open.
func open_device(id: String) -> bool:
	if server == null:
		return false
	var was_running: bool = is_running()
	var opened: bool = server.call(&"open_device", id)
	if opened and was_running:
		start()
	status_changed.emit()
	return opened


## Id of the open device ("" when none).
func get_device_id() -> String:
	return str(server.call(&"get_device_id")) if server != null else ""


## Name of the open device ("" when none).
func get_device_name() -> String:
	return str(server.call(&"get_device_name")) if server != null else ""


## True when the open device is the simulated one (its hand can be moved).
func is_simulated() -> bool:
	return get_device_id() == DEFAULT_DEVICE


## Starts the servo thread at [param rate_hz] (250–4000).
func start(rate_hz: float = 1000.0) -> bool:
	if server == null:
		return false
	var started: bool = server.call(&"start", rate_hz)
	status_changed.emit()
	return started


## Stops the servo thread; the device is left at zero force.
func stop() -> void:
	if server != null:
		server.call(&"stop")
		status_changed.emit()


## True while the servo thread renders.
func is_running() -> bool:
	if server == null:
		return false
	var running: bool = server.call(&"is_running")
	return running


## Sends the latest haptic frame (layout in gdextension/src/godot/conversions.h).
func submit_frame(frame: Dictionary) -> bool:
	if server == null:
		return false
	var accepted: bool = server.call(&"submit_frame", frame)
	return accepted


## Queues an impact transient: direction, speed (m/s) and optionally gain, frequency, decay.
func push_impact(impact: Dictionary) -> bool:
	if server == null:
		return false
	var accepted: bool = server.call(&"push_impact", impact)
	return accepted


## The device's input vector (length ≤ 1); zero without a device.
func get_input_vector() -> Vector2:
	return server.call(&"get_input_vector") if server != null else Vector2.ZERO


## Rendered force components in newtons, one [Vector2] per name in [constant FORCE_NAMES].
func get_forces() -> Dictionary:
	if server != null:
		return server.call(&"get_forces")
	var zeros: Dictionary = {}
	for force_name: String in FORCE_NAMES:
		zeros[force_name] = Vector2.ZERO
	return zeros


## Servo loop statistics (rate_hz, period_p99_ms, late_ticks, realtime…); empty without
## the extension.
func get_stats() -> Dictionary:
	return server.call(&"get_stats") if server != null else {}


## The open device's force limit in newtons (0 without a device).
func get_max_force() -> float:
	if server == null:
		return 0.0
	var limits: Dictionary = server.call(&"get_device_limits")
	var max_force: float = limits.get("max_force", 0.0)
	return max_force


## Moves the simulated device's hand to a normalised workspace position.
func set_hand_target(normalized: Vector2) -> void:
	var radius: float = _workspace_radius()
	if radius > 0.0:
		server.call(&"set_hand_target", normalized.limit_length(1.0) * radius)


## The simulated hand's target, normalised.
func get_hand_target() -> Vector2:
	var radius: float = _workspace_radius()
	if radius <= 0.0:
		return Vector2.ZERO
	var target: Vector2 = server.call(&"get_hand_target")
	return target / radius


## The device's stylus position, normalised.
func get_stylus_position() -> Vector2:
	var radius: float = _workspace_radius()
	if radius <= 0.0:
		return Vector2.ZERO
	var position: Vector2 = server.call(&"get_device_position")
	return position / radius


## Renderer: "movement" (acceleration control, the default) or "constraint" (position
## control against walls set with [method set_constraint_geometry]).
func set_render_mode(mode: String) -> bool:
	if server == null:
		return false
	var accepted: bool = server.call(&"set_render_mode", mode)
	status_changed.emit()
	return accepted


## The current renderer's name ("" without the extension).
func get_render_mode() -> String:
	return str(server.call(&"get_render_mode")) if server != null else ""


## Walls for the constraint renderer as point pairs in maze units (pixels), and how the
## maze maps onto the workspace: {maze_min, maze_max, workspace ("disc"/"square"),
## half_extent (m, 0 = the device's radius)}.
func set_constraint_geometry(segments: PackedVector2Array, mapping: Dictionary) -> bool:
	if server == null:
		return false
	var accepted: bool = server.call(&"set_constraint_geometry", segments, mapping)
	return accepted


## The constraint proxy: position (maze units), goal, constraints, placed; empty without
## the extension.
func get_proxy_state() -> Dictionary:
	return server.call(&"get_proxy_state") if server != null else {}


## Changes settings of one section (force_model, smoothing, safety, telemetry, constraint);
## only the keys given change. Refused settings are reported and change nothing.
func configure(section: String, values: Dictionary) -> bool:
	if server == null:
		return false
	var accepted: bool = server.call(&"set_config", section, values)
	return accepted


## The extension's version line, or an explanation of why there is none.
func get_version() -> String:
	if server == null:
		return "haptics extension not loaded"
	return str(server.call(&"get_version"))


## Setter of [member force_scale], clamped to [0, 2].
func set_force_scale(value: float) -> void:
	force_scale = clampf(value, 0.0, 2.0) if is_finite(value) else force_scale
	status_changed.emit()


## Setter of [member smoothing_enabled].
func set_smoothing_enabled(value: bool) -> void:
	smoothing_enabled = value
	if server != null:
		server.call(&"set_config", "smoothing", {"enabled": value})
	status_changed.emit()


## Setter of [member control_mode]; unknown modes are refused with an error.
func set_control_mode(value: StringName) -> void:
	if value != CONTROL_DEVICE and value != CONTROL_KEYBOARD:
		push_error("Haptics.control_mode: unknown mode '%s' (device or keyboard)" % value)
		return
	control_mode = value
	status_changed.emit()


func _workspace_radius() -> float:
	if server == null:
		return 0.0
	var limits: Dictionary = server.call(&"get_device_limits")
	var radius: float = limits.get("workspace_radius", 0.0)
	return radius


# Keyboard/gamepad deflection wins; otherwise the mouse's offset from the window centre,
# a quarter of the window's height being the workspace edge.
func _hand_from_user_input() -> Vector2:
	var keys: Vector2 = Input.get_vector(&"move_left", &"move_right", &"move_up", &"move_down")
	if not keys.is_zero_approx() or not _mouse_seen:
		return keys
	var viewport: Viewport = get_viewport()
	var size: Vector2 = viewport.get_visible_rect().size
	var offset: Vector2 = viewport.get_mouse_position() - size * 0.5
	return (offset / (size.y * 0.25)).limit_length(1.0)
