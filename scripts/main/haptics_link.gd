class_name HapticsLink
extends RefCounted
## Typed, tolerant access to the [code]Haptics[/code] autoload for the UI and game flow.
##
## Every call checks that the autoload and the method exist, so the menus, the HUD and the
## autopilot work with any version of the autoload and without the native extension
## (answers are then zeros, empty, or [code]false[/code]).

## Force components the server reports, in drawing order (total last).
const FORCE_COMPONENTS: Array[String] = [
	"normal", "friction", "weight", "drag", "inertia", "impact", "total"
]
## Maximum force assumed when the device reports none (Touch / Omni peak), in newtons.
const FALLBACK_MAX_FORCE: float = 3.3


## The autoload node, or null when it is not registered.
static func node() -> Node:
	var loop: SceneTree = Engine.get_main_loop() as SceneTree
	if loop == null or loop.root == null:
		return null
	return loop.root.get_node_or_null(^"Haptics")


## True when the native extension is loaded.
static func is_available() -> bool:
	return _call_bool(&"is_available")


## Every device present, the simulated one first; empty without the extension.
static func list_devices() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var value: Variant = _call(&"list_devices")
	if value is Array:
		var entries: Array = value
		for entry: Variant in entries:
			if entry is Dictionary:
				out.append(entry)
	return out


## Opens the device [param id]; false when it failed or there is no extension.
static func open_device(id: String) -> bool:
	return _call_bool(&"open_device", [id])


## Id of the open device, or an empty string.
static func get_device_id() -> String:
	var value: Variant = _call(&"get_device_id")
	return str(value) if value != null else ""


## Name of the open device, or an empty string.
static func get_device_name() -> String:
	var value: Variant = _call(&"get_device_name")
	return str(value) if value != null else ""


## Whether the servo loop runs.
static func is_running() -> bool:
	return _call_bool(&"is_running")


## The device's input vector in game axes (y down), length at most 1.
static func get_input_vector() -> Vector2:
	return _call_vector(&"get_input_vector")


## Rendered force components (newtons, game axes), one per key of
## [constant FORCE_COMPONENTS]; missing components are zero.
static func get_forces() -> Dictionary:
	var forces: Dictionary = {}
	var value: Variant = _call(&"get_forces")
	if value is Dictionary:
		forces = value
	return forces


## Servo loop statistics ([code]rate_hz[/code], [code]period_p99_ms[/code], ...).
static func get_stats() -> Dictionary:
	var value: Variant = _call(&"get_stats")
	if value is Dictionary:
		var stats: Dictionary = value
		return stats
	return {}


## The device's maximum force in newtons ([constant FALLBACK_MAX_FORCE] when unknown).
static func get_max_force() -> float:
	var value: Variant = _call(&"get_max_force")
	if typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT:
		var newtons: float = value
		if newtons > 0.0:
			return newtons
	return FALLBACK_MAX_FORCE


## Moves the simulated device's hand target (each axis in [-1, 1], game axes).
static func set_hand_target(normalized: Vector2) -> void:
	_call(&"set_hand_target", [normalized])


## The simulated device's hand target, normalised to the workspace.
static func get_hand_target() -> Vector2:
	return _call_vector(&"get_hand_target")


## The device's stylus position, normalised to the workspace.
static func get_stylus_position() -> Vector2:
	return _call_vector(&"get_stylus_position")


## Sets the autoload's [code]force_scale[/code] when it has one.
static func set_force_scale(value: float) -> void:
	_set_property(&"force_scale", value)


## Sets the autoload's [code]smoothing_enabled[/code] when it has one.
static func set_smoothing_enabled(value: bool) -> void:
	_set_property(&"smoothing_enabled", value)


## Sets the autoload's [code]control_mode[/code] when it has one.
static func set_control_mode(value: StringName) -> void:
	_set_property(&"control_mode", value)


## The autoload's [code]control_mode[/code] ([code]&"keyboard"[/code] when it has none).
static func get_control_mode() -> StringName:
	var haptics: Node = node()
	if haptics == null or not (&"control_mode" in haptics):
		return &"keyboard"
	var mode: StringName = StringName(str(haptics.get(&"control_mode")))
	return mode


## Whether the mouse, keyboard and gamepad move the simulated hand (the autoload's
## [code]hand_follows_input[/code]); the autopilot turns it off.
static func set_hand_follows_input(value: bool) -> void:
	_set_property(&"hand_follows_input", value)


## Servo rate in Hz, or 0 when the loop is not running.
static func get_rate_hz() -> float:
	var stats: Dictionary = get_stats()
	var value: Variant = stats.get("rate_hz", 0.0)
	if typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT:
		var rate: float = value
		return rate
	return 0.0


## Reads one force component of [param forces] as a [Vector2] (zero when absent).
static func force_of(forces: Dictionary, component: String) -> Vector2:
	var value: Variant = forces.get(component, Vector2.ZERO)
	if value is Vector2:
		var force: Vector2 = value
		return force
	return Vector2.ZERO


static func _call(method: StringName, args: Array = []) -> Variant:
	var haptics: Node = node()
	if haptics == null or not haptics.has_method(method):
		return null
	return haptics.callv(method, args)


static func _call_bool(method: StringName, args: Array = []) -> bool:
	var value: Variant = _call(method, args)
	return typeof(value) == TYPE_BOOL and value


static func _call_vector(method: StringName) -> Vector2:
	var value: Variant = _call(method)
	if value is Vector2:
		var vector: Vector2 = value
		return vector
	return Vector2.ZERO


static func _set_property(property: StringName, value: Variant) -> void:
	var haptics: Node = node()
	if haptics != null and property in haptics:
		haptics.set(property, value)
