extends TestSuite
## The road and the crashes through [HapticVehicle3D] on the drive scene's car, real physics,
## the door of the test's own stepped at 1 kHz of device time ([DriveRig]): a kerb's ripple at
## the speed over its spacing, with its amplitude; one impact for one crash into the wall, none
## for the chassis striking the ground on a landing; a refused frame; the renderer taken and
## given back; a ground body of two surfaces felt shape by shape.

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true
const KERB := preload("res://addons/haptics/materials/kerb.tres")
const HapticCrashGauge := preload("res://addons/haptics/vehicle/haptic_crash_gauge.gd")
## A ripple is counted where it crosses these (N), both ways: the kerb's light roughness
## near zero makes no extra cycle.
const HYSTERESIS_N := 0.2
## Where the drop happens: open pad, far from the kerbs, the gravel and the wall.
const PAD_START := Vector3(-80.0, 0.6, -20.0)
## The car is dropped from this high over its standing place (m).
const DROP_HEIGHT := 3.0

var door: HapticsTestKit.Door = null
var rig: DriveRig = null
var _texture: PackedFloat64Array = PackedFloat64Array()
var _impact_peak: float = 0.0


func before_each() -> void:
	set_timeout(120.0)
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.instant(door) and HapticsTestKit.no_dead_zone(door))
	_texture = PackedFloat64Array()
	_impact_peak = 0.0


func after_each() -> void:
	if rig != null and is_instance_valid(rig.scene):
		rig.scene.free()
	rig = null


func test_a_kerb_ripples_at_the_speed_over_its_spacing() -> void:
	# Straight down the middle at 10 m/s: the left wheels run over the first kerb.
	rig = DriveRig.new(self, door, DriveScene.START, 0.0, false)
	rig.target_speed = 10.0
	await rig.drive(150)  # Up to speed before the kerb.
	var speeds: PackedFloat64Array = PackedFloat64Array()
	rig.on_tick = _record_texture_on_kerb
	for frame_index: int in 150:
		await rig.drive(1)
		for wheel: HapticTyreContact in rig.car.haptics.last_frame.wheels:
			if wheel.ripple_n > 0.0:
				speeds.append(wheel.speed_m_per_s)
	rig.on_tick = Callable()
	if not assert_gt(_texture.size(), 300, "a third of a second on the kerb at least"):
		return
	var mean_speed: float = 0.0
	for speed: float in speeds:
		mean_speed += speed / speeds.size()
	var expected_hz: float = mean_speed / KERB.ripple_spacing
	var measured_hz: float = _cycles(_texture) / (_texture.size() * HapticsTestKit.DT)
	var largest: float = 0.0
	for x: float in _texture:
		largest = maxf(largest, absf(x))
	print(
		(
			(
				"kerb at %.2f m/s over %.2f m ridges: %.1f Hz felt (expected %.1f Hz), peak %.2f N "
				+ "(ripple %.2f N) over %d ticks"
			)
			% [
				mean_speed,
				KERB.ripple_spacing,
				measured_hz,
				expected_hz,
				largest,
				KERB.ripple,
				_texture.size()
			]
		)
	)
	assert_almost_eq(mean_speed, 10.0, 0.6, "at speed")
	assert_almost_eq(measured_hz, expected_hz, expected_hz * 0.08, "speed / spacing")
	assert_almost_eq(largest, KERB.ripple, KERB.ripple * 0.3, "the kerb's amplitude")
	assert_gt(rig.state().frames, 250, "a frame every physics tick")


func test_hitting_the_wall_rings_one_impact() -> void:
	rig = DriveRig.new(self, door, Vector3(0.0, 0.6, DriveScene.WALL_AT.y - 25.0), 0.0, false)
	rig.target_speed = 9.0
	var crashes: Array[float] = []
	rig.car.haptics.crashed.connect(
		func(_collider: Object, speed: float) -> void: crashes.append(speed)
	)
	rig.on_tick = _record_impact
	for frame_index: int in 300:
		await rig.drive(1)
		if not crashes.is_empty():
			rig.cruise = false  # Off the throttle once it has hit.
			rig.car.throttle = 0.0
	print("crash into the wall: %s m/s, impact peak %.2f N on the wheel" % [crashes, _impact_peak])
	assert_eq(crashes.size(), 1, "one crash")
	assert_eq(rig.car.haptics.crashes_played, 1)
	if crashes.size() == 1:
		assert_gt(crashes[0], 5.0, "sized by the change of velocity: it was doing about 9 m/s")
	assert_gt(_impact_peak, 0.5, "the wheel was kicked")


func test_a_drop_onto_the_ground_is_no_crash() -> void:
	# Dropped flat from DROP_HEIGHT, the car lands at 7.7 m/s: its suspensions bottom out
	# and the chassis strikes the pad, which the driver feels in the seat, not in the wheel.
	rig = DriveRig.new(self, door, PAD_START + Vector3.UP * DROP_HEIGHT, 0.0, false)
	rig.cruise = false
	var crashes: Array[float] = []
	rig.car.haptics.crashed.connect(
		func(_collider: Object, speed: float) -> void: crashes.append(speed)
	)
	rig.on_tick = _record_impact
	var velocity_before: Vector3 = rig.car.linear_velocity
	var touch_change: float = -1.0  # The change of velocity over the tick the chassis touched.
	var touch_normal: Vector3 = Vector3.ZERO
	var peak_load_ratio: float = 0.0
	for frame_index: int in 120:
		await rig.drive(1)
		var change: float = (rig.car.linear_velocity - velocity_before).length()
		velocity_before = rig.car.linear_velocity
		var frame: HapticVehicleFrame = rig.car.haptics.last_frame
		for wheel: HapticTyreContact in frame.wheels:
			peak_load_ratio = maxf(peak_load_ratio, wheel.load_n / frame.reference_load_n)
		var state: PhysicsDirectBodyState3D = PhysicsServer3D.body_get_direct_state(
			rig.car.get_rid()
		)
		if touch_change < 0.0 and state.get_contact_count() > 0:
			touch_change = change
			touch_normal = state.get_contact_local_normal(0)
	print(
		(
			(
				"drop from %.1f m: the chassis struck the pad with %.2f m/s of change (normal %s), "
				+ "the front loads peaked at %.2f x the reference; crashes %s, impact peak %.2f N"
			)
			% [DROP_HEIGHT, touch_change, touch_normal, peak_load_ratio, crashes, _impact_peak]
		)
	)
	# The old rule (any new touch changing the velocity by crash_min_speed) made it a crash.
	assert_gt(touch_change, rig.car.haptics.crash_min_speed, "struck hard enough to count")
	assert_gt(touch_normal.y, cos(rig.car.haptics.crash_ground_angle), "from below: ground")
	assert_true(crashes.is_empty(), "the ground is no crash")
	assert_eq(rig.car.haptics.crashes_played, 0)
	assert_almost_eq(_impact_peak, 0.0, 1e-9, "no impact on the wheel")


func test_one_ground_body_of_two_surfaces_is_felt_shape_by_shape() -> void:
	# An imported level's ground: the gravel's shape moved into the pad's body and the gravel
	# declared on that shape only. The car drives straight from the asphalt onto it.
	rig = DriveRig.new(self, door, Vector3(-20.0, 0.6, -52.0), 0.0, false)
	var pad: StaticBody3D = rig.scene.get_node("Pad")
	var patch: StaticBody3D = rig.scene.get_node("Gravel")
	var shape: CollisionShape3D = patch.find_children("*", "CollisionShape3D", false, false)[0]
	var gravel: HapticMaterial = patch.get_meta(&"haptic_material")
	shape.reparent(pad)
	shape.set_meta(&"haptic_material", gravel)
	patch.remove_meta(&"haptic_material")
	var steered: Array[VehicleWheel3D] = []
	for child: Node in rig.car.get_children():
		if child is VehicleWheel3D and (child as VehicleWheel3D).use_as_steering:
			steered.append(child)
	rig.target_speed = 6.0
	var off: PackedFloat64Array = PackedFloat64Array()
	var on: PackedFloat64Array = PackedFloat64Array()
	for frame_index: int in 300:
		await rig.drive(1)
		var wheels: Array[HapticTyreContact] = rig.car.haptics.last_frame.wheels
		for i: int in wheels.size():
			var at: Vector3 = steered[i].get_contact_point()
			var inside: bool = at.x > -29.5 and at.x < -10.5 and at.z > -39.5 and at.z < -10.5
			var outside: bool = at.z < -40.5 or at.z > -9.5 or at.x < -30.5 or at.x > -9.5
			if wheels[i].in_contact and inside:
				on.append(wheels[i].grip)
			elif wheels[i].in_contact and outside:
				off.append(wheels[i].grip)
	print(
		(
			"grip off the gravel %s, on it %s (%d, %d frames)"
			% [_range(off), _range(on), off.size(), on.size()]
		)
	)
	if not (
		assert_gt(off.size(), 50, "on the asphalt first")
		and assert_gt(on.size(), 50, "then on the gravel")
	):
		return
	assert_almost_eq(_range(off).x, _range(off).y, 1e-9, "one grip on the asphalt")
	assert_almost_eq(_range(on).x, _range(off).x * gravel.grip, 1e-6, "the gravel's on its shape")
	assert_almost_eq(_range(on).y, _range(off).x * gravel.grip, 1e-6, "and only that")


func test_a_touch_within_45_degrees_of_up_is_ground() -> void:
	var body: RigidBody3D = autofree(RigidBody3D.new())
	var gauge: HapticCrashGauge = HapticCrashGauge.new(body)
	assert_almost_eq(gauge.ground_angle_rad, deg_to_rad(45.0), 1e-9, "the default")
	var ground: Array[bool] = []
	for degrees: float in [0.0, 30.0, 44.0, 46.0, 60.0, 90.0, 180.0]:
		var normal: Vector3 = Vector3.UP.rotated(Vector3.RIGHT, deg_to_rad(degrees))
		ground.append(gauge.is_ground(normal, Vector3.UP))
	# Flat ground, a 30 degree ramp, a steep bank are ground; a 60 degree face, a wall, a
	# touch from above are not.
	assert_eq(ground, [true, true, true, false, false, false, false] as Array[bool])
	# Up is against the car's gravity: where an area turns it to +z, a floor facing +y is a wall.
	assert_true(gauge.is_ground(Vector3.BACK, Vector3.BACK))
	assert_false(gauge.is_ground(Vector3.UP, Vector3.BACK))


func test_a_refused_frame_names_its_field_and_the_last_good_one_stays() -> void:
	rig = DriveRig.new(self, door, DriveScene.START, 0.0, false)
	await rig.drive(60)
	var vehicle: HapticsVehicle = rig.car.haptics.renderer()
	var frames: int = rig.state().frames
	var bad: HapticVehicleFrame = rig.car.haptics.build_frame()
	bad.wheels[0].load_n = NAN
	expect_error("wheels[0].load_n: not finite")
	assert_false(vehicle.send_frame(bad))
	bad = rig.car.haptics.build_frame()
	bad.wheels[1].slip_angle_rad = 2.0
	expect_error("wheels[1].slip_angle_rad")
	assert_false(vehicle.send_frame(bad))
	for tick: int in 20:
		door.servo.step(HapticsTestKit.DT)
	assert_eq(rig.state().frames, frames, "nothing taken")
	assert_true(is_finite(door.get_forces_3d().total.x))


func test_the_node_takes_the_renderer_and_gives_it_back() -> void:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.input.dead_zone = 0.1
	assert_true(door.servo.apply_settings(settings))
	assert_eq(door.get_render_mode(), &"movement")
	rig = DriveRig.new(self, door, DriveScene.START, 0.0, false)
	assert_eq(door.get_render_mode(), HapticsVehicle.NAME)
	assert_eq(door.servo.get_settings().input.dead_zone, 0.0, "a wheel's centre has no play")
	rig.scene.free()
	assert_eq(door.get_render_mode(), &"movement", "given back when it leaves")
	assert_almost_eq(door.servo.get_settings().input.dead_zone, 0.1, 1e-9, "and the dead zone")


func _record_texture_on_kerb(on: DriveRig) -> void:
	for wheel: HapticTyreContact in on.car.haptics.last_frame.wheels:
		if wheel.ripple_n > 0.0:
			_texture.append(on.part(DriveRig.TEXTURE))
			return


func _record_impact(on: DriveRig) -> void:
	_impact_peak = maxf(_impact_peak, absf(on.door.get_forces_3d().impact.x))


# Full cycles through +HYSTERESIS_N and back below -HYSTERESIS_N.
func _cycles(samples: PackedFloat64Array) -> int:
	var count: int = 0
	var high: bool = false
	for x: float in samples:
		if not high and x > HYSTERESIS_N:
			high = true
			count += 1
		elif high and x < -HYSTERESIS_N:
			high = false
	return count


# The smallest and largest of samples.
func _range(samples: PackedFloat64Array) -> Vector2:
	var out: Vector2 = Vector2(INF, -INF)
	for x: float in samples:
		out = Vector2(minf(out.x, x), maxf(out.y, x))
	return out
