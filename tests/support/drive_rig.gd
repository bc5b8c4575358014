class_name DriveRig
extends RefCounted
## The drive scene ([DriveScene]) for vehicle tests: the real scene with its car and its
## [HapticVehicle3D], on a door of the test's own stepped 20 servo ticks (1 ms each) for every
## 50 Hz physics frame, with a speed held by a throttle controller, and the brush tyre model
## in GDScript to compare the servo's rim force with (docs/vehicle.md's formulas).

## Servo ticks a physics frame: 1 kHz of device time for each 50 Hz frame.
const TICKS_PER_FRAME := 20
const ALIGNING := HapticVehicleFacts.VehicleForce.ALIGNING
const TEXTURE := HapticVehicleFacts.VehicleForce.TEXTURE

## The test's door.
var door: HapticsTestKit.Door = null
## The scene, in the test's tree.
var scene: DriveScene = null
## The car.
var car: DriveCar = null
## The speed the throttle holds, m/s, along the car's heading.
var target_speed: float = 0.0
## Hold [member target_speed] (off: the car's throttle is left as it is).
var cruise: bool = true
## Called with this rig after each servo tick, when set (a recorder).
var on_tick: Callable = Callable()


## The scene under [param parent] on [param test_door], the car at [param at] heading
## [param heading] (rad from +z toward +x), its keys off. With [param by_device] off the door
## is in keyboard control, so the test steers the car itself.
func _init(
	parent: Node, test_door: HapticsTestKit.Door, at: Vector3, heading: float, by_device: bool
) -> void:
	door = test_door
	door.control_mode = &"device" if by_device else &"keyboard"
	scene = (load("res://game/level3d/drive/drive.tscn") as PackedScene).instantiate() as DriveScene
	scene.haptics = door
	parent.add_child(scene)
	car = scene.car
	car.use_keys = false
	scene.place_car(at, heading)


## Runs [param frames] physics frames, holding [member target_speed], stepping the servo.
func drive(frames: int) -> void:
	for i: int in frames:
		await scene.get_tree().physics_frame
		if cruise:
			car.throttle = clampf(0.6 * (target_speed - car.forward_speed()), -1.0, 1.0)
		for tick: int in TICKS_PER_FRAME:
			door.servo.step(HapticsTestKit.DT)
			if on_tick.is_valid():
				on_tick.call(self)


## The servo's latest force component [param part] on the device's x, newtons.
func part(part_index: int) -> float:
	return door.get_forces_3d().parts[part_index].x


## The renderer's state after the latest tick.
func state() -> HapticVehicleState:
	return car.haptics.renderer().get_state()


## The rim force the model gives for [param frame] (its wheels at their own slip angles)
## with [param settings]: -peak_force / (n F_ref |M_kp|max per load) × sum fade × M_kp, each
## load capped at max_load_ratio × F_ref.
static func model_rim_force(frame: HapticVehicleFrame, settings: HapticVehicleSettings) -> float:
	var a: float = settings.contact_half_length_m
	var trail: float = settings.mechanical_trail_m
	var peak_slide: float = minf(1.0, (a + 3.0 * trail) / (4.0 * a))
	var rest: float = 1.0 - peak_slide
	var peak_per_load: float = (
		a * peak_slide * rest * rest * rest
		+ 3.0 * trail * peak_slide * (1.0 - peak_slide + peak_slide * peak_slide / 3.0)
	)
	var max_load: float = settings.max_load_ratio * frame.reference_load_n
	var torque: float = 0.0
	for wheel: HapticTyreContact in frame.wheels:
		var fade: float = minf(1.0, wheel.speed_m_per_s / settings.low_speed_m_per_s)
		var wheel_load: float = minf(wheel.load_n, max_load) if wheel.in_contact else 0.0
		torque += fade * kingpin_torque(settings, wheel_load, wheel.slip_angle_rad, wheel.grip)
	var peak: float = frame.wheels.size() * frame.reference_load_n * peak_per_load
	return -settings.peak_force_n / peak * torque


## The brush model's torque about the steering axis, N m (rolling forward).
static func kingpin_torque(
	settings: HapticVehicleSettings, wheel_load: float, slip: float, grip: float
) -> float:
	if grip * wheel_load <= 0.0:
		return 0.0
	var lam: float = settings.cornering_coefficient_per_rad / (3.0 * grip) * tan(slip)
	var size: float = absf(lam)
	var lateral: float = grip * wheel_load * signf(lam)
	var aligning: float = 0.0
	if size < 1.0:
		lateral = grip * wheel_load * lam * (3.0 - 3.0 * size + lam * lam)
		aligning = -grip * wheel_load * settings.contact_half_length_m * lam * pow(1.0 - size, 3.0)
	return aligning - settings.mechanical_trail_m * lateral
