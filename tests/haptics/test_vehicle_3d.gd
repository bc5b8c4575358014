extends TestSuite
## [HapticVehicle3D] on a real [VehicleBody3D]: the drive scene's car ([DriveCar]) with the
## real extension, on a door of the test's own stepped at 1 kHz of device time for each 50 Hz
## physics frame ([DriveRig]). Standing, its wheels' measured loads carry its weight; on a
## skid-pad the wheel is pulled back toward straight ahead with the model's force; steered by
## the device, the hand's own grip settles short of where it holds the wheel.

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true
## Where the skid-pad circles start: far from the kerbs, the gravel and the wall.
const PAD_START := Vector3(-80.0, 0.6, -20.0)
const HapticTyreGauge := preload("res://addons/haptics/vehicle/haptic_tyre_gauge.gd")

var door: HapticsTestKit.Door = null
var rig: DriveRig = null


func before_each() -> void:
	set_timeout(120.0)
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.instant(door) and HapticsTestKit.no_dead_zone(door))


func after_each() -> void:
	if rig != null and is_instance_valid(rig.scene):
		rig.scene.free()
	rig = null


func test_standing_the_wheels_carry_the_cars_weight() -> void:
	rig = DriveRig.new(self, door, PAD_START, 0.0, false)
	# Made before the car's first physics tick, as the node makes its own: the wheels are
	# where their suspensions attach.
	var gauges: Array[HapticTyreGauge] = []
	for child: Node in rig.car.get_children():
		if child is VehicleWheel3D:
			gauges.append(HapticTyreGauge.new(child as VehicleWheel3D))
	await rig.drive(150)
	var total: float = 0.0
	for gauge: HapticTyreGauge in gauges:
		total += gauge.load_n(rig.car)
	var weight: float = rig.car.mass * ProjectSettings.get_setting("physics/3d/default_gravity")
	assert_almost_eq(total, weight, weight * 0.02, "the four suspensions hold the car up")
	var frame: HapticVehicleFrame = rig.car.haptics.last_frame
	assert_eq(frame.wheels.size(), 2, "the two steered wheels")
	assert_almost_eq(frame.reference_load_n, weight / 4.0, 1.0)
	for wheel: HapticTyreContact in frame.wheels:
		assert_true(wheel.in_contact)
		assert_almost_eq(
			wheel.load_n, weight / 4.0, weight * 0.05, "a front wheel: about a quarter"
		)
		assert_lt(wheel.speed_m_per_s, 0.05, "standing")
	assert_almost_eq(rig.part(DriveRig.ALIGNING), 0.0, 0.01, "no torque standing still")


func test_on_a_skid_pad_the_wheel_is_pulled_back_toward_straight_ahead() -> void:
	# Steering held at 0.12 rad at 10 m/s: a circle of about 22 m, 0.45 g.
	for steer: float in [0.12, -0.12]:
		if rig != null:
			rig.scene.free()
		rig = DriveRig.new(self, door, PAD_START, 0.0, false)
		rig.target_speed = 10.0
		rig.car.steering = steer
		await rig.drive(250)
		var frame: HapticVehicleFrame = rig.car.haptics.last_frame
		var state: HapticVehicleState = rig.state()
		var settings: HapticVehicleSettings = rig.car.haptics.renderer().get_settings()
		var expected: float = DriveRig.model_rim_force(frame, settings)
		var felt: float = rig.part(DriveRig.ALIGNING)
		var yaw_rate: float = rig.car.angular_velocity.y
		print(
			(
				(
					"skid-pad, steering %+.2f rad at %.1f m/s, %.1f m radius: slips %.2f / %.2f deg, "
					+ "loads %.0f / %.0f N, torque %.1f N m, rim force %+.3f N (model %+.3f N)"
				)
				% [
					steer,
					rig.car.forward_speed(),
					rig.car.forward_speed() / absf(yaw_rate),
					rad_to_deg(frame.wheels[0].slip_angle_rad),
					rad_to_deg(frame.wheels[1].slip_angle_rad),
					frame.wheels[0].load_n,
					frame.wheels[1].load_n,
					state.aligning_torque_nm,
					felt,
					expected
				]
			)
		)
		assert_almost_eq(rig.car.forward_speed(), 10.0, 0.5, "held at speed")
		assert_gt(yaw_rate * signf(steer), 0.3, "turning the way it is steered")
		# Turned left (steer > 0), the tyres pull the rim right (+x): back toward straight.
		assert_gt(felt * signf(steer), 0.3, "pulled back toward straight ahead")
		assert_lt(state.aligning_torque_nm * signf(steer), 0.0, "the torque turns the wheels back")
		assert_almost_eq(felt, expected, absf(expected) * 0.05, "the model's force")
		assert_gt(state.slide_fraction, 0.05, "slipping")
		assert_lt(state.slide_fraction, 1.0, "not sliding")
		for wheel: HapticTyreContact in frame.wheels:
			assert_gt(wheel.slip_angle_rad * signf(steer), 0.0, "steered into the turn")


func test_steered_by_the_device_the_hand_is_pulled_toward_the_centre() -> void:
	rig = DriveRig.new(self, door, PAD_START, 0.0, true)
	rig.target_speed = 10.0
	# The hand holds the wheel a quarter of the way left.
	assert_true(
		door.device.set_hand_target_3d(
			Vector3(-0.25 * door.device.get_workspace_radius(), 0.0, 0.0)
		)
	)
	await rig.drive(250)
	var steering: float = rig.car.haptics.get_steering()
	assert_true(rig.car.haptics.device_steers())
	assert_true(rig.car.haptics.last_frame.steered_by_device)
	assert_almost_eq(rig.car.steering, rig.car.haptics.get_steering_angle(), 1e-6)
	assert_gt(rig.car.angular_velocity.y, 0.3, "turning left")
	assert_gt(rig.part(DriveRig.ALIGNING), 0.3, "the wheel pulls right, toward the centre")
	# The hand's grip gives (300 N/m): the wheel settles right of where the hand holds it, by
	# the pull over the grip.
	var pull: float = door.get_forces_3d().total.x
	var given: float = pull / 300.0 / door.device.get_workspace_radius()
	assert_almost_eq(-steering, -0.25 + given, 0.02, "the hand gives by the pull")
	assert_gt(steering, 0.0, "still turned left")
	assert_lt(steering, 0.25, "short of the hand's hold")


func test_the_steering_input_is_the_devices_x() -> void:
	rig = DriveRig.new(self, door, PAD_START, 0.0, true)
	var radius: float = door.device.get_workspace_radius()
	assert_true(door.device.set_hand_target_3d(Vector3(0.5 * radius, 0.0, 0.0)))
	await rig.drive(25)
	assert_almost_eq(rig.car.haptics.get_steering(), -0.5, 0.02, "right is negative, as steering")
	assert_almost_eq(
		rig.car.haptics.get_steering_angle(), -0.5 * DriveCar.STEER_LOCK, 0.02 * DriveCar.STEER_LOCK
	)
	door.control_mode = &"keyboard"
	assert_false(rig.car.haptics.device_steers(), "keyboard control: the game steers by keys")
