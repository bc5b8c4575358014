extends Node
## The trial's driver, copied into a copy of Godot's demo 2d/physics_platformer (Godot 4
## version) with the haptics addon installed (physics_platformer.sh). It loads the demo's own
## stage, puts a HapticProbe on its RigidBody2D player (pixels_per_metre by the addon's rule
## from the project's gravity), and plays a scripted run: the device's hand walks the player
## (the project feeds move_left/move_right from it), jump and spawn are pressed like keys.
## Phases: settle (the first drop), jumps, walls (the pit's pillars), enemy (the demo's
## "spawn" drops one on the head), seesaw, lift (a ride down on MovingPlatform1).
##
## Ground truth comes from the physics server, not the probe: a landing is a floor contact
## (normal up) after at least AIRBORNE_S without one, a wall hit a side contact after
## AIRBORNE_S without one on that side, each at the velocity the player entered the step with,
## relative to the collider. Prints one TRIAL line per phase and quits.

const AIRBORNE_S := 0.15
const MIN_IMPACT_M_PER_S := 0.2
const PLANK_MASS := 5.10204
const PROBE_SCRIPT := "res://addons/haptics/probe/haptic_probe.gd"
## Frames an impact may come after the ground truth's event and still be its.
const MATCH_FRAMES := 3
## The lift rides down for 3 s; boarded at its top, the ride is watched this long.
const RIDE_FRAMES := 340
## A run that has not ended by now (the lift never came) ends anyway.
const MAX_FRAMES := 6000

var _player: RigidBody2D = null
var _probe: Node = null
var _ppm: float = 100.0
var _frame: int = 0
var _phase: String = ""
var _stats: Dictionary = {}
var _order: PackedStringArray = []
var _v_in: Vector2 = Vector2.ZERO
var _since_floor: int = 100000
var _since_left: int = 100000
var _since_right: int = 100000
var _events: Array[Dictionary] = []
var _impacts: Array[Dictionary] = []
var _columns: Dictionary = {}
var _stride: int = 0
var _script: Array[Dictionary] = []
var _lift: Node2D = null
var _lift_boarded: int = -1
var _boarding: bool = false
var _spawned_at: int = -1


func _ready() -> void:
	process_physics_priority = 1000
	var stage: Node = (load("res://stage.tscn") as PackedScene).instantiate()
	add_child(stage)
	_player = stage.get_node(^"Player") as RigidBody2D
	_lift = stage.get_node(^"Props/MovingPlatform1") as Node2D
	var gravity: float = ProjectSettings.get_setting("physics/2d/default_gravity")
	var probe_script: GDScript = load(PROBE_SCRIPT)
	_probe = probe_script.new()
	# The addon's rule: the gravity the player falls with over Earth's.
	_ppm = gravity / float(probe_script.get_script_constant_map()["EARTH_GRAVITY"])
	_probe.set(&"pixels_per_metre", _ppm)
	_probe.set(&"default_material", load("res://addons/haptics/materials/hard.tres"))
	_probe.connect(&"impact", _on_impact)
	_player.add_child(_probe)
	Haptics.hand_follows_input = false
	Haptics.device.set_hand_target(Vector2.ZERO)
	var names: PackedStringArray = Haptics.servo.get_telemetry_columns()
	for i: int in names.size():
		_columns[names[i]] = i
	_stride = names.size()
	Haptics.servo.drain_telemetry(4096)
	_plan()


func _plan() -> void:
	_at("settle", 0, {})
	var t: int = 120
	for jump: int in 3:
		_at("jumps", t, {"press": "jump"})
		_at("jumps", t + 18, {"release": "jump"})
		t += 170
	for lap: int in 2:
		_at("walls", t, {"hand": Vector2.RIGHT})
		_at("walls", t + 120, {"hand": Vector2.ZERO})
		_at("walls", t + 150, {"hand": Vector2.LEFT})
		_at("walls", t + 270, {"hand": Vector2.ZERO})
		t += 300
	_at("enemy", t, {"hand": Vector2(0.3, 0.0)})
	_at("enemy", t + 40, {"hand": Vector2.ZERO})
	_at("enemy", t + 100, {"spawn": true})
	t += 460
	_at("seesaw", t, {"teleport": Vector2(1221.0, 385.0)})
	t += 300
	_at("seesaw", t, {"board": true})


func _at(phase: String, frame: int, action: Dictionary) -> void:
	action["phase"] = phase
	action["frame"] = frame
	_script.append(action)


func _physics_process(_delta: float) -> void:
	_observe()
	while not _script.is_empty() and _script[0]["frame"] <= _frame:
		var step: Dictionary = _script.pop_front()
		_enter(step["phase"])
		_act(step)
	if _spawned_at >= 0 and (_frame - _spawned_at) % 30 == 0 and _frame - _spawned_at <= 120:
		for node: Node in _player.get_parent().get_children():
			if node is RigidBody2D and node != _player:
				var offset: Vector2 = (node as Node2D).position - _player.position
				if offset.length() < 80.0:
					print("TRIAL enemy at %s from the player, frame %d" % [offset, _frame])
	if _boarding:
		_ride_lift()
	_frame += 1
	if _frame > MAX_FRAMES:
		_enter("end")
	if _phase == "end":
		_report()
		get_tree().quit(0)


func _enter(phase: String) -> void:
	if phase == _phase:
		return
	_phase = phase
	if not _stats.has(phase):
		_order.append(phase)
		_stats[phase] = {
			"landings": 0, "landings_felt": 0, "walls": 0, "walls_felt": 0, "impacts": 0,
			"extra": 0, "speeds": PackedStringArray(), "peak_impact_n": 0.0, "head": 0,
			"weight": 0, "doubled": 0, "plank_load": 0, "pushed": 0, "push_n": 0.0,
			"lift_lost": 0,
		}


func _act(step: Dictionary) -> void:
	if step.has("press"):
		_key(step["press"], true)
	if step.has("release"):
		_key(step["release"], false)
	if step.has("hand"):
		var hand: Vector2 = step["hand"]
		Haptics.device.set_hand_target(hand)
	if step.has("teleport"):
		_teleport(step["teleport"])
	if step.has("spawn"):
		# What the demo's "spawn" action calls (deferred from _integrate_forces, where its
		# is_action_just_pressed misses a scripted press): an enemy 50 px above the player.
		_player.call(&"_spawn_enemy_above")
		_spawned_at = _frame
		# The demo's enemies wake when a VisibleOnScreenEnabler2D sees them on screen, which
		# never happens headless: the new one is woken by hand.
		var enemy: Node = _player.get_parent().get_child(-1)
		for child: Node in enemy.get_children():
			if child is VisibleOnScreenEnabler2D:
				child.free()
		enemy.process_mode = Node.PROCESS_MODE_ALWAYS
	if step.has("board"):
		_boarding = true


# As a key would: an event parsed before the next physics frame (the demo reads
# is_action_just_pressed in _integrate_forces, which an action_press here would miss).
func _key(action: String, pressed: bool) -> void:
	var event: InputEventAction = InputEventAction.new()
	event.action = action
	event.pressed = pressed
	Input.parse_input_event(event)


func _teleport(where: Vector2) -> void:
	var rid: RID = _player.get_rid()
	PhysicsServer2D.body_set_state(rid, PhysicsServer2D.BODY_STATE_TRANSFORM, Transform2D(0.0, where))
	PhysicsServer2D.body_set_state(rid, PhysicsServer2D.BODY_STATE_LINEAR_VELOCITY, Vector2.ZERO)
	_since_floor = 0  # a placement is no landing


# Boards the lift at the top of its ride (the animation turns there, 3 s into its 6 s loop).
func _ride_lift() -> void:
	if _lift_boarded < 0:
		if _lift.position.y < 304.5:
			_enter("lift")
			_teleport(_lift.position + Vector2(0.0, -12.0 - 14.0 - 1.0))
			_lift_boarded = _frame
		return
	if _frame - _lift_boarded > RIDE_FRAMES:
		_enter("end")


func _on_impact(_collider: Object, normal: Vector2, speed: float) -> void:
	_impacts.append({"frame": _frame, "normal": normal, "speed": speed, "phase": _phase})
	var stats: Dictionary = _stats.get(_phase, {})
	if stats.is_empty():
		return
	stats["impacts"] += 1
	var speeds: PackedStringArray = stats["speeds"]
	speeds.append("%.2f" % speed)
	stats["speeds"] = speeds


func _observe() -> void:
	if _phase.is_empty():
		return
	var stats: Dictionary = _stats[_phase]
	var state: PhysicsDirectBodyState2D = PhysicsServer2D.body_get_direct_state(_player.get_rid())
	var step_frames: int = int(AIRBORNE_S * Engine.physics_ticks_per_second)
	var floor_n: Vector2 = Vector2.ZERO
	var floor_speed: float = 0.0
	var side: Dictionary = {}
	var on_head: bool = false
	for i: int in state.get_contact_count():
		var n: Vector2 = state.get_contact_local_normal(i)
		var relative: Vector2 = _v_in - state.get_contact_collider_velocity_at_position(i)
		var speed: float = -relative.dot(n) / _ppm
		var collider: Object = state.get_contact_collider_object(i)
		if n.y < -0.6:
			floor_n = n
			floor_speed = maxf(floor_speed, speed)
		elif absf(n.x) > 0.7:
			side[signf(n.x)] = maxf(side.get(signf(n.x), 0.0), speed)
		elif n.y > 0.6 and collider is RigidBody2D:
			on_head = true  # the only rigid bodies about are enemies (and bullets, not fired)
	if floor_n != Vector2.ZERO:
		if _since_floor >= step_frames and floor_speed >= MIN_IMPACT_M_PER_S:
			_event(stats, "landings", floor_speed)
		_since_floor = 0
	else:
		_since_floor += 1
	for side_sign: float in [1.0, -1.0]:
		var touching: bool = side.has(side_sign)
		var since: int = _since_left if side_sign > 0.0 else _since_right
		if touching and since >= step_frames and float(side[side_sign]) >= MIN_IMPACT_M_PER_S:
			_event(stats, "walls", side[side_sign])
		since = 0 if touching else since + 1
		if side_sign > 0.0:
			_since_left = since
		else:
			_since_right = since
	var frame: Object = _probe.get(&"last_frame")
	var resting: Array = frame.get(&"resting")
	var contacts: Array = frame.get(&"contacts")
	if on_head:
		stats["head"] += 1
		for entry: Object in resting:
			if absf(float(entry.get(&"mass_kg")) - 1.0) < 1e-3:
				stats["weight"] += 1
				break
	for entry: Object in resting:
		if absf(float(entry.get(&"mass_kg")) - PLANK_MASS) < 1e-3:
			stats["plank_load"] += 1
			break
	var doubled: bool = false
	for i: int in contacts.size():
		for j: int in range(i + 1, contacts.size()):
			var a: Vector2 = contacts[i].get(&"normal")
			var b: Vector2 = contacts[j].get(&"normal")
			doubled = doubled or a.dot(b) > 0.999
	stats["doubled"] += 1 if doubled else 0
	if _phase == "lift" and _lift_boarded >= 0 and floor_n == Vector2.ZERO and _since_floor == 1:
		stats["lift_lost"] += 1
	_read_forces(stats, not side.is_empty())
	_v_in = state.get_linear_velocity()
	_match_impacts()


func _event(stats: Dictionary, kind: String, speed: float) -> void:
	stats[kind] += 1
	_events.append({"frame": _frame, "kind": kind, "speed": speed, "phase": _phase})


# Each ground-truth event is felt if an impact came within MATCH_FRAMES of it; an impact
# that belongs to no event is extra.
func _match_impacts() -> void:
	while not _impacts.is_empty() and _impacts[0]["frame"] < _frame - MATCH_FRAMES:
		var impact: Dictionary = _impacts.pop_front()
		var matched: bool = false
		for event: Dictionary in _events:
			if absi(int(event["frame"]) - int(impact["frame"])) <= MATCH_FRAMES and not event.has("felt"):
				event["felt"] = true
				var stats: Dictionary = _stats[event["phase"]]
				stats[str(event["kind"]) + "_felt"] += 1
				matched = true
				break
		if not matched:
			_stats[impact["phase"]]["extra"] += 1


func _read_forces(stats: Dictionary, against_wall: bool) -> void:
	var samples: PackedFloat32Array = Haptics.servo.drain_telemetry(512)
	var push: float = 0.0
	for s: int in range(0, samples.size() - _stride + 1, _stride):
		var impact: Vector2 = Vector2(samples[s + _columns["impact_x"]], samples[s + _columns["impact_y"]])
		stats["peak_impact_n"] = maxf(stats["peak_impact_n"], impact.length())
		push = maxf(push, absf(samples[s + _columns["normal_x"]]))
	if against_wall and _phase == "walls":
		stats["pushed"] += 1 if push >= 0.5 else 0
		stats["push_n"] = maxf(stats["push_n"], push)


func _report() -> void:
	_match_impacts()
	print("TRIAL | phase | landings felt/all | wall hits felt/all | impacts (extra) | impact speeds m/s | peak impact N | enemy on head: weight/frames | doubled-surface frames | plank-as-load frames | wall push >=0.5 N frames (max N) | lift: floor lost |")
	for phase: String in _order:
		if phase == "end":
			continue
		var s: Dictionary = _stats[phase]
		print(
			"TRIAL | %s | %d/%d | %d/%d | %d (%d) | %s | %.2f | %d/%d | %d | %d | %d (%.2f) | %d |"
			% [
				phase, s["landings_felt"], s["landings"], s["walls_felt"], s["walls"],
				s["impacts"], s["extra"], " ".join(s["speeds"]) if not s["speeds"].is_empty() else "-",
				s["peak_impact_n"], s["weight"], s["head"], s["doubled"], s["plank_load"],
				s["pushed"], s["push_n"], s["lift_lost"],
			]
		)
	print("TRIAL pixels_per_metre %.2f; events: %s" % [_ppm, _events.map(func(e: Dictionary) -> String: return "%s@%d %.2f%s" % [e["kind"], e["frame"], e["speed"], "" if e.has("felt") else " UNFELT"])])
