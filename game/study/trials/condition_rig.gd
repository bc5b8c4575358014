class_name ConditionRig
extends Node
## Puts one study condition into effect on a [StudyLevel]: the control scheme, the renderer
## and the forces, through the [code]Haptics[/code] autoload's servo.
## [br][br]
## [b]none[/b] and [b]movement[/b]: acceleration control; the render mode is
## [code]movement[/code] with the condition's [code]contact_model[/code]; a [StudyProbe],
## the player's only probe (the one its scene brings is removed), submits the frames with
## the forces the condition enables (none: [code]Haptics.force_scale[/code] 0, so nothing is
## felt).
## [b]constraint[/b]: position control; the level's wall outlines and the [MazeMap] go to
## the native finite-proxy renderer, the render mode is [code]constraint[/code], and the
## player becomes a follower drawn where the proxy is (its own physics is off; the probe
## only sends heartbeat frames). With the simulated device, the mouse (pointing into the
## maze) or the arrow keys move its hand in this condition.
## [br][br]
## Call [method setup] once per level and condition, then [method hold] (avatar frozen, no
## force: before a trial starts) or [method go] (live), and [method release] before the
## level goes away or the condition changes. The caller saves and restores the autoload's
## settings around the study ([method save_haptics], [method restore_haptics]).

## Speed of the simulated hand under the arrow keys in position control, maze units/s.
const KEY_SPEED: float = 420.0
## Below this force (newtons) the device counts as settled (see [method is_settled]).
const SETTLED_FORCE_N: float = 0.005

## The condition in effect ([code]none[/code], [code]movement[/code], [code]constraint[/code]).
var condition: String = ""
## Its settings ([method StudyConfig.condition]).
var settings: Dictionary = {}
var level: StudyLevel = null
## The level's avatar.
var player: Player = null
## The avatar's only probe while the condition is set up: [method setup] removes the ones
## the avatar came with (the player scene's own) before adding it.
var probe: StudyProbe = null
## Maze ↔ workspace map (position control; also valid for the others).
var map: MazeMap = null
## Whether the condition is live (see [method go]).
var is_live: bool = false
## When true a script steers the simulated hand ([method set_hand]); the mouse and keys do
## not.
var piloted: bool = false:
	set(value):
		piloted = value
		if level != null:
			_update_hand_following()
## Where the mouse points in the level (maze units); the simulated hand follows it in
## position control. Unset: the level's own idea of the mouse position.
var pointer: Callable = Callable()

var _hand_point: Vector2 = Vector2.ZERO
var _mouse_moved: bool = false
var _last_proxy: Vector2 = Vector2.ZERO


func _ready() -> void:
	process_physics_priority = -10


## The autoload's settings the study changes, to give back with [method restore_haptics].
static func save_haptics() -> Dictionary:
	var saved: Dictionary = {
		"force_scale": Haptics.force_scale,
		"smoothing": Haptics.smoothing_enabled,
		"control_mode": Haptics.control_mode,
		"hand_follows_input": Haptics.hand_follows_input,
	}
	if Haptics.is_available():
		saved["render_mode"] = Haptics.get_render_mode()
		saved["servo"] = Haptics.servo.get_settings()
		saved["movement"] = HapticsMovement.of(Haptics).get_settings()
		saved["constraint"] = HapticsConstraint.of(Haptics).get_settings()
	return saved


## Gives back what [method save_haptics] saved.
static func restore_haptics(saved: Dictionary) -> void:
	if saved.is_empty():
		return
	var force_scale: float = saved["force_scale"]
	var smoothing: bool = saved["smoothing"]
	var follows: bool = saved["hand_follows_input"]
	Haptics.control_mode = StringName(str(saved["control_mode"]))
	Haptics.hand_follows_input = follows
	if Haptics.is_available() and saved.has("render_mode"):
		var servo_settings: HapticServoSettings = saved["servo"]
		var movement_settings: HapticMovementSettings = saved["movement"]
		var constraint_settings: HapticConstraintSettings = saved["constraint"]
		Haptics.set_render_mode(StringName(str(saved["render_mode"])))
		Haptics.servo.apply_settings(servo_settings)
		HapticsMovement.of(Haptics).apply_settings(movement_settings)
		HapticsConstraint.of(Haptics).apply_settings(constraint_settings)
	else:
		Haptics.force_scale = force_scale
		Haptics.smoothing_enabled = smoothing


## Prepares [param p_condition] on [param p_level] with [param p_settings]; the avatar is
## held (see [method hold]). Returns false when the servo refused something.
func setup(p_level: StudyLevel, p_condition: String, p_settings: Dictionary) -> bool:
	level = p_level
	player = level.player
	condition = p_condition
	settings = p_settings
	var radius: float = 0.1
	if Haptics.is_available():
		radius = Haptics.device.get_workspace_radius()
	var half_extent: float = settings.get("half_extent", 0.0)
	map = MazeMap.new(
		level.get_bounds(), str(settings.get("workspace", "disc")), half_extent, radius
	)
	_remove_probes(player)
	probe = StudyProbe.new()
	probe.name = "StudyProbe"
	probe.configure(settings)
	player.add_child(probe)
	player.use_keyboard = false
	Haptics.control_mode = Haptics.CONTROL_DEVICE
	_hand_point = level.get_spawn_position()
	var ok: bool = true
	if Haptics.is_available():
		var servo_settings: HapticServoSettings = Haptics.servo.get_settings()
		servo_settings.telemetry.enabled = true
		servo_settings.telemetry.decimation = 1
		ok = Haptics.servo.apply_settings(servo_settings)
		if StudyFormat.is_position_control(condition):
			ok = _send_constraint() and ok
		else:
			ok = _set_contact_model(str(settings.get("contact_model", "paper_sum"))) and ok
	hold()
	return ok


## Freezes the avatar and renders no force (movement renderer, no contacts, smoothing off
## so nothing lingers: the next condition starts from exactly zero).
func hold() -> void:
	is_live = false
	Haptics.set_render_mode(&"movement")
	Haptics.force_scale = 0.0
	Haptics.smoothing_enabled = false
	probe.heartbeat_only = true
	probe.drive_input = false
	player.set_physics_process(false)
	player.velocity = Vector2.ZERO
	player.input_vector = Vector2.ZERO
	player.physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_INHERIT
	_update_hand_following()


## Makes the condition live: forces on, the avatar moves.
func go() -> void:
	is_live = true
	var smoothing: bool = settings.get("smoothing", true)
	Haptics.smoothing_enabled = smoothing
	if StudyFormat.is_position_control(condition):
		Haptics.force_scale = 1.0
		HapticsConstraint.of(Haptics).activate()
		probe.heartbeat_only = true
		probe.drive_input = false
		player.set_physics_process(false)
		player.physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_OFF
		_last_proxy = player.global_position
	else:
		var force_scale: float = settings.get("force_scale", 1.0)
		Haptics.force_scale = force_scale
		Haptics.set_render_mode(&"movement")
		probe.heartbeat_only = false
		probe.drive_input = true
		player.set_physics_process(true)
		player.reset_physics_interpolation()
	_update_hand_following()


## Undoes [method setup]: the probe goes, the avatar is an ordinary body again, the movement
## renderer is back and the mouse moves the simulated hand again.
func release() -> void:
	is_live = false
	Haptics.set_render_mode(&"movement")
	if is_instance_valid(probe):
		_remove_probe(probe)
	probe = null
	if is_instance_valid(player):
		player.set_physics_process(true)
		player.physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_INHERIT
	if not piloted:
		Haptics.hand_follows_input = true


## The [HapticProbe]s on [param body] (the avatar): while a condition is set up, exactly
## one, the rig's [member probe].
static func probes_on(body: Node) -> Array[HapticProbe]:
	var out: Array[HapticProbe] = []
	if body == null:
		return out
	for child: Node in body.get_children():
		if child is HapticProbe:
			out.append(child as HapticProbe)
	return out


## Puts the avatar back on the level's start, at rest (acceleration control).
func respawn() -> void:
	player.global_position = level.get_spawn_position()
	player.velocity = Vector2.ZERO
	player.reset_physics_interpolation()


## Where the avatar is, in maze units (in position control: the proxy).
func avatar_position() -> Vector2:
	return player.global_position


## The constraint renderer's proxy (null outside position control).
func proxy_state() -> HapticProxyState:
	if not StudyFormat.is_position_control(condition) or not is_live:
		return null
	return HapticsConstraint.of(Haptics).get_proxy()


## The normalised hand position a trial starts from: the centre (acceleration control) or
## the point over the level's start (position control).
func start_hand() -> Vector2:
	if StudyFormat.is_position_control(condition):
		return map.hand_of(level.get_spawn_position())
	return Vector2.ZERO


## Whether the device renders (next to) no force: a trial starts only then, so nothing
## felt before it (a wall at the end of the previous trial) carries over.
func is_settled() -> bool:
	return Haptics.get_forces().total.length() < SETTLED_FORCE_N


## The device's current normalised position (game axes).
func hand_position() -> Vector2:
	return Haptics.device.get_position()


## Moves the simulated hand to [param normalised] (a participant that steers the hand).
func set_hand(normalised: Vector2) -> void:
	Haptics.device.set_hand_target(normalised)


func _process(delta: float) -> void:
	if level == null or probe == null:
		return
	if StudyFormat.is_position_control(condition):
		_drive_simulated_hand(delta)
		if is_live:
			_follow_proxy(delta)


func _physics_process(delta: float) -> void:
	if probe != null and is_live and StudyFormat.is_position_control(condition):
		_follow_proxy(delta)


func _input(event: InputEvent) -> void:
	if event is InputEventMouseMotion:
		_mouse_moved = true


# The follower: the avatar is drawn where the proxy is, its velocity estimated for the
# hull's pose.
func _follow_proxy(delta: float) -> void:
	var state: HapticProxyState = proxy_state()
	if state == null:
		return
	var proxy: Vector2 = state.proxy
	player.global_position = proxy
	if delta > 0.0:
		player.velocity = player.velocity.lerp((proxy - _last_proxy) / delta, 0.3)
	_last_proxy = proxy


# Position control with the simulated device: the mouse points into the maze, the arrow
# keys push the hand; the real devices move by themselves.
func _drive_simulated_hand(delta: float) -> void:
	if piloted or not Haptics.device.is_simulated():
		return
	var keys: Vector2 = Input.get_vector(&"move_left", &"move_right", &"move_up", &"move_down")
	if not keys.is_zero_approx():
		_hand_point += keys * KEY_SPEED * delta
		_mouse_moved = false
	elif _mouse_moved:
		var point: Variant = pointer.call() if pointer.is_valid() else null
		_hand_point = point if point is Vector2 else level.get_global_mouse_position()
	var area: Rect2 = map.bounds
	_hand_point = _hand_point.clamp(area.position, area.end)
	Haptics.device.set_hand_target(map.hand_of(_hand_point))


func _update_hand_following() -> void:
	var own_hand: bool = (
		piloted or (StudyFormat.is_position_control(condition) and Haptics.device.is_simulated())
	)
	Haptics.hand_follows_input = not own_hand


# Every probe already on the avatar goes, at once: the player scene brings its own (the
# side-scroller's, material "hard" with impacts), and a probe only queued for deletion
# still submits frames this tick. Two probes would take turns at the servo's frame and
# push their own impacts: the condition would render what neither configuration says.
func _remove_probes(body: Node) -> void:
	for other: HapticProbe in probes_on(body):
		_remove_probe(other)


func _remove_probe(other: HapticProbe) -> void:
	var parent: Node = other.get_parent()
	if parent != null:
		parent.remove_child(other)
	other.queue_free()


func _send_constraint() -> bool:
	var constraint: HapticsConstraint = HapticsConstraint.of(Haptics)
	var update_name: String = str(settings.get("update", "servo"))
	var update: int = HapticsValue.choice_value(HapticConstraintFacts.ProxyUpdate, update_name)
	if update < 0:
		push_error("ConditionRig: unknown constraint update '%s'." % update_name)
		return false
	var constraint_settings: HapticConstraintSettings = constraint.get_settings()
	constraint_settings.stiffness_n_per_m = settings.get("stiffness", 300.0)
	constraint_settings.proxy_radius = Player.RADIUS
	constraint_settings.update = update as HapticConstraintFacts.ProxyUpdate
	constraint_settings.max_iterations = settings.get("max_iterations", 6)
	var ok: bool = constraint.apply_settings(constraint_settings)
	var sent: bool = constraint.set_walls(level.get_wall_segments(), map)
	return ok and sent


func _set_contact_model(model_name: String) -> bool:
	var model: int = HapticsValue.choice_value(HapticMovementFacts.ContactModel, model_name)
	if model < 0:
		push_error("ConditionRig: unknown contact model '%s'." % model_name)
		return false
	var movement: HapticsMovement = HapticsMovement.of(Haptics)
	var movement_settings: HapticMovementSettings = movement.get_settings()
	movement_settings.force_model.contact_model = model as HapticMovementFacts.ContactModel
	return movement.apply_settings(movement_settings)
