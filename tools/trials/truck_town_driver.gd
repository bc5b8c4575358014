extends Node
## The trial's driver, copied into a copy of Godot's demo 3d/truck_town with the haptics addon
## installed and a HapticVehicle3D on its tow truck (truck_town.sh). It loads the town with the
## tow truck as the demo's car select does, and drives it with the demo's own vehicle.gd: the
## device's hand steers (hand_follows_input off, the simulated hand moved by the script), the
## throttle is the demo's "accelerate" action, held to a target speed.
## Phases, each from a placement of the whole truck (its chain and towed car with it):
## turn (the hand 0.4 left at about 7.5 m/s on the flat ground outside the town), lock (full
## lock at about 8 m/s), crash (into House07's wall at about 9 m/s), grass (the town's grass,
## its collider declaring gravel's road, see _declare_grass), landing (a
## drop of 2 m at 8 m/s with the hand 0.2 left, standing in for a hill: the load cap).
##
## Ground truth comes from the physics server: the chassis's contacts, a new collider (not
## touched for the node's 0.3 s) being a touch, ground when its normal is within 45 degrees of
## up, else a wall, with the change of velocity over that tick. Prints one TRIAL line per phase.

const TICKS := 120.0
## Outside the town the ground is the demo's OuterGround box, flat at y = 0 and 2 km wide.
const FLAT := Vector3(0.0, 0.6, 80.0)
## The road at y = 5.2 north of House07 (x -16..-12), its wall 11 m ahead (from z 21 the
## chassis grounded on a step at z 19 and never got there).
const CRASH := Vector3(-14.0, 5.8, 16.0)
## The town's flat grass west of the road, at y = 0.4.
const GRASS := Vector3(-57.0, 1.0, -41.0)
const GRAVEL := "res://addons/haptics/materials/gravel.tres"

var _car: VehicleBody3D = null
var _haptic: HapticVehicle3D = null
var _vehicle: HapticsVehicle = null
var _bodies: Array[RigidBody3D] = []
var _columns: Dictionary[String, int] = {}
var _stride: int = 0
var _plan: Array[Dictionary] = []
var _phase: Dictionary = {}
var _frame: int = 0
var _target_speed: float = 0.0
var _velocity_before: Vector3 = Vector3.ZERO
var _touching: Dictionary[int, int] = {}
var _rows: PackedStringArray = []


func _ready() -> void:
	# Before the car's _physics_process, so the throttle and the hand are this tick's.
	process_physics_priority = -100
	var town: Node3D = (load("res://town/town_scene.tscn") as PackedScene).instantiate()
	var truck: Node3D = (load("res://vehicles/tow_truck.tscn") as PackedScene).instantiate()
	truck.name = "car"
	town.call(&"setup", truck, func() -> void: pass, false)
	add_child(town)
	_car = truck.get_child(0) as VehicleBody3D
	_haptic = _car.get_node(^"HapticVehicle3D") as HapticVehicle3D
	_haptic.crashed.connect(_on_crashed)
	_vehicle = _haptic.renderer()
	for child: Node in truck.get_children():
		if child is RigidBody3D:
			_bodies.append(child as RigidBody3D)
	_declare_grass(town.get_node(^"TownModel/Terrain") as StaticBody3D)
	Haptics.hand_follows_input = false
	Haptics.device.set_hand_target(Vector2.ZERO)
	var names: PackedStringArray = Haptics.servo.get_telemetry_columns()
	for i: int in names.size():
		_columns[names[i]] = i
	_stride = names.size()
	Haptics.servo.drain_telemetry(4096)
	var limits: HapticDeviceLimits = Haptics.device.get_capabilities().limits
	print(
		(
			"TRIAL device %s: limit %.2f N peak, %.2f N continuous; renderer %s (%s), %s"
			% [
				Haptics.device.get_name(),
				limits.max_force_n,
				limits.max_continuous_force_n,
				Haptics.get_render_mode(),
				"available" if _vehicle.is_available() else "missing",
				"device steers" if _haptic.device_steers() else "keys steer",
			]
		)
	)
	_plan = [
		_step("turn", FLAT, Vector3.LEFT, 3.0, 7.5, 360, Vector2(-0.4, 0.0), 600, 360),
		_step("lock", FLAT, Vector3.LEFT, 3.0, 8.0, 360, Vector2(-1.0, 0.0), 600, 420),
		_step("crash", CRASH, Vector3.FORWARD, 9.0, 9.0, 0, Vector2.ZERO, 360, 0),
		_step("grass", GRASS, Vector3.RIGHT, 7.0, 7.0, 60, Vector2(-0.15, 0.0), 300, 60),
		_step(
			"landing",
			FLAT + Vector3(0.0, 2.0, 0.0),
			Vector3.LEFT,
			8.0,
			8.0,
			0,
			Vector2(-0.2, 0.0),
			240,
			0
		),
	]
	_next_phase()


# One phase: placed at where facing heading at speed0, held at speed, the hand put at hand from
# frame hand_at, measured from frame measure_from to frames.
func _step(
	phase: String,
	where: Vector3,
	heading: Vector3,
	speed0: float,
	speed: float,
	hand_at: int,
	hand: Vector2,
	frames: int,
	measure_from: int,
) -> Dictionary:
	return {
		"name": phase,
		"where": where,
		"heading": heading,
		"speed0": speed0,
		"speed": speed,
		"hand_at": hand_at,
		"hand": hand,
		"frames": frames,
		"from": measure_from,
	}


# The demo's grass and road are shapes of one body (TownModel/Terrain, from the glTF's
# OMI_physics_body). As a developer would in an import script, the grass collider declares
# gravel's road as its own material; the body declares none.
func _declare_grass(terrain: StaticBody3D) -> void:
	terrain.get_node(^"GrassCollider").set_meta(&"haptic_material", load(GRAVEL))


func _next_phase() -> void:
	if _plan.is_empty():
		var heads: PackedStringArray = [
			"phase",
			"speed m/s",
			"steering rad",
			"rim force N: mean [min..max]",
			"device x peak N",
			"slide",
			"grip",
			"texture peak N",
			"max load / reference",
			"chassis touches: walls, ground",
			"crashes played (m/s, what)",
			"impact peak N",
		]
		print("TRIAL | %s |" % " | ".join(heads))
		for row: String in _rows:
			print(row)
		get_tree().quit(0)
		return
	_phase = _plan.pop_front()
	_phase["stats"] = {
		"speed": 0.0,
		"steer": 0.0,
		"rim": 0.0,
		"rim_min": INF,
		"rim_max": -INF,
		"n": 0,
		"device_peak": 0.0,
		"slide": 0.0,
		"grip": 0.0,
		"texture": 0.0,
		"load": 0.0,
		"walls": PackedStringArray(),
		"ground": 0,
		"crashes": PackedStringArray(),
		"impact": 0.0,
		"hand_speed": 0.0,
	}
	_frame = 0
	_target_speed = _phase["speed"]
	Haptics.device.set_hand_target(Vector2.ZERO)
	_place(_phase["where"], _phase["heading"], _phase["speed0"])


# Places the truck, its chain and its towed car as one, moving along heading at speed.
func _place(where: Vector3, heading: Vector3, speed: float) -> void:
	var basis: Basis = Basis.looking_at(-heading, Vector3.UP)  # a VehicleBody3D drives along +z
	var move: Transform3D = Transform3D(basis, where) * _car.global_transform.affine_inverse()
	for body: RigidBody3D in _bodies:
		body.global_transform = move * body.global_transform
		body.linear_velocity = heading * speed
		body.angular_velocity = Vector3.ZERO
		body.reset_physics_interpolation()
	_velocity_before = heading * speed
	_touching.clear()


func _physics_process(_delta: float) -> void:
	if _frame == int(_phase["hand_at"]):
		Haptics.device.set_hand_target(_phase["hand"])
		_phase["stats"]["hand_speed"] = _forward_speed()
	_throttle()
	_observe()
	_frame += 1
	if _frame >= int(_phase["frames"]):
		_rows.append(_row())
		_next_phase()


func _forward_speed() -> float:
	return _car.linear_velocity.dot(_car.global_transform.basis.z)


# The demo's analog throttle, pressed in proportion to the speed missing.
func _throttle() -> void:
	var missing: float = _target_speed - _forward_speed()
	if missing > 0.0:
		Input.action_press(&"accelerate", clampf(0.3 + missing, 0.0, 1.0))
	else:
		Input.action_release(&"accelerate")


func _observe() -> void:
	var stats: Dictionary = _phase["stats"]
	_touches(stats)
	var samples: PackedFloat32Array = Haptics.servo.drain_telemetry(1024)
	var measuring: bool = _frame >= int(_phase["from"])
	for s: int in range(0, samples.size() - _stride + 1, _stride):
		var impact: Vector3 = Vector3(
			samples[s + _columns["impact_x"]],
			samples[s + _columns["impact_y"]],
			samples[s + _columns["impact_z"]]
		)
		stats["impact"] = maxf(stats["impact"], impact.length())
		if measuring:
			stats["device_peak"] = maxf(
				stats["device_peak"], absf(samples[s + _columns["total_x"]])
			)
	var frame: HapticVehicleFrame = _haptic.last_frame
	for wheel: HapticTyreContact in frame.wheels:
		stats["load"] = maxf(stats["load"], wheel.load_n / frame.reference_load_n)
	if not measuring:
		return
	var state: HapticVehicleState = _vehicle.get_state()
	stats["n"] += 1
	stats["speed"] += _forward_speed()
	stats["steer"] += _car.steering
	stats["rim"] += state.rim_force_n
	stats["rim_min"] = minf(stats["rim_min"], state.rim_force_n)
	stats["rim_max"] = maxf(stats["rim_max"], state.rim_force_n)
	stats["slide"] += state.slide_fraction
	stats["texture"] = maxf(stats["texture"], absf(state.texture_n))
	var grip: float = 0.0
	for wheel: HapticTyreContact in frame.wheels:
		grip += wheel.grip / maxf(1, frame.wheels.size())
	stats["grip"] += grip


# The chassis's touches as the physics server reports them, each new collider once.
func _touches(stats: Dictionary) -> void:
	var velocity: Vector3 = _car.linear_velocity
	var change: float = (velocity - _velocity_before).length()
	_velocity_before = velocity
	var state: PhysicsDirectBodyState3D = PhysicsServer3D.body_get_direct_state(_car.get_rid())
	var now: int = Engine.get_physics_frames()
	for i: int in state.get_contact_count():
		# A collider's ground and its walls are told apart (a house's ledge, then its wall).
		var ground: bool = (
			state.get_contact_local_normal(i).dot(Vector3.UP) >= cos(deg_to_rad(45.0))
		)
		var id: int = state.get_contact_collider_id(i) * 2 + (1 if ground else 0)
		var known: bool = _touching.has(id) and now - _touching[id] <= int(0.3 * TICKS)
		_touching[id] = now
		if known:
			continue
		var collider: Node = state.get_contact_collider_object(i) as Node
		if ground:
			stats["ground"] += 1
		else:
			var walls: PackedStringArray = stats["walls"]
			walls.append("%.1f %s" % [change, collider.name if collider != null else "?"])
			stats["walls"] = walls


func _on_crashed(collider: Object, speed: float) -> void:
	var stats: Dictionary = _phase["stats"]
	var crashes: PackedStringArray = stats["crashes"]
	crashes.append("%.1f %s" % [speed, (collider as Node).name if collider is Node else "?"])
	stats["crashes"] = crashes


func _row() -> String:
	var s: Dictionary = _phase["stats"]
	var n: float = maxf(1.0, s["n"])
	var walls: PackedStringArray = s["walls"]
	var crashes: PackedStringArray = s["crashes"]
	return (
		(
			"TRIAL | %s | %.2f (hand at %.2f) | %+.3f | %+.2f [%+.2f..%+.2f] | %.2f | %.2f"
			+ " | %.2f | %.2f | %.2f | %d: %s; %d | %d: %s | %.2f |"
		)
		% [
			_phase["name"],
			s["speed"] / n,
			s["hand_speed"],
			s["steer"] / n,
			s["rim"] / n,
			s["rim_min"],
			s["rim_max"],
			s["device_peak"],
			s["slide"] / n,
			s["grip"] / n,
			s["texture"],
			s["load"],
			walls.size(),
			", ".join(walls),
			s["ground"],
			crashes.size(),
			", ".join(crashes),
			s["impact"],
		]
	)
