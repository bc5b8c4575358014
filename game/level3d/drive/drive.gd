class_name DriveScene
extends Node3D
## A small driving scene: a car ([DriveCar]) with a [HapticVehicle3D] on a wide asphalt pad,
## with kerbs to ride over, a gravel patch and a wall ahead. On a wheel device the steering
## pulls back toward straight as the car corners, goes light when the front tyres let go,
## ripples over the kerbs, rumbles on the gravel and kicks in a crash. Built in code: the
## scene runs on its own (F6) with nothing but the Haptics autoload.
## [br][br]
## Arrows (or the device's wheel) steer, Up drives, Down brakes and reverses, R puts the car
## back at the start, Esc leaves.

## The player asked to leave (Esc). Nobody listening: the scene runs on its own and quits.
signal menu_requested

## Where the car starts, and its heading (+z, toward the wall).
const START := Vector3(0.0, 0.6, -60.0)
## The kerb under the left wheels on the way to the wall (x-z corners).
const KERB_LEFT: Array[Vector2] = [Vector2(0.25, -40.0), Vector2(1.45, -30.0)]
## The kerb under the right wheels after it.
const KERB_RIGHT: Array[Vector2] = [Vector2(-1.45, -20.0), Vector2(-0.25, -10.0)]
## The gravel patch off to the right.
const GRAVEL: Array[Vector2] = [Vector2(-30.0, -40.0), Vector2(-10.0, -10.0)]
## The wall across the way ahead (x-z size, centre).
const WALL_SIZE := Vector2(30.0, 1.0)
const WALL_AT := Vector2(0.0, 40.0)
## The chase camera's place behind and above the car, and how far ahead it looks.
const CAMERA_BEHIND := 7.5
const CAMERA_UP := 3.0
const CAMERA_AHEAD := 4.0

## The car.
var car: DriveCar = null
## The door the car's [HapticVehicle3D] talks to; the autoload unless set before the scene
## enters the tree (a test's own).
var haptics: HapticVehicle3D.Haptics = null

var _camera: Camera3D = null
var _status: Label = null


func _ready() -> void:
	var track: DriveTrack = DriveTrack.new(self)
	track.daylight()
	track.pad()
	track.kerb(KERB_LEFT[0], KERB_LEFT[1])
	track.kerb(KERB_RIGHT[0], KERB_RIGHT[1])
	track.gravel(GRAVEL[0], GRAVEL[1])
	track.wall(WALL_SIZE, WALL_AT)
	car = DriveCar.new()
	car.name = "Car"
	if haptics != null:
		car.haptics.haptics = haptics
	car.position = START
	add_child(car)
	_camera = Camera3D.new()
	_camera.fov = 65.0
	# Placed every frame from the car's interpolated transform: not interpolated itself.
	_camera.physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_OFF
	add_child(_camera)
	_camera.make_current()
	_follow()
	_status = StatusLine.add_to(self, 18)


func _process(_delta: float) -> void:
	_follow()
	var steering: String = "device" if car.haptics.device_steers() else "keys"
	var state: HapticVehicleState = car.haptics.renderer().get_state()
	var speed: float = car.forward_speed()
	_status.text = (
		"%.0f km/h%s   steering: %s   wheel pull %+.2f N   Arrows: drive   R: restart   Esc: leave"
		% [absf(speed) * 3.6, " reverse" if speed < -0.5 else "", steering, state.rim_force_n]
	)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		if menu_requested.get_connections().is_empty():
			get_tree().quit()
		else:
			menu_requested.emit()
	elif (
		event is InputEventKey and event.is_pressed() and (event as InputEventKey).keycode == KEY_R
	):
		restart()


## Puts the car back at the start, standing.
func restart() -> void:
	place_car(START, 0.0)


## Puts the car at [param at] heading [param heading] radians from +z (positive: toward +x),
## standing still.
func place_car(at: Vector3, heading: float) -> void:
	car.global_transform = Transform3D(Basis(Vector3.UP, heading), at)
	car.linear_velocity = Vector3.ZERO
	car.angular_velocity = Vector3.ZERO
	car.reset_physics_interpolation()


func _follow() -> void:
	var body: Transform3D = car.get_global_transform_interpolated()
	var ahead: Vector3 = body.basis.z
	ahead.y = 0.0
	ahead = ahead.normalized() if not ahead.is_zero_approx() else Vector3.BACK
	var eye: Vector3 = body.origin - ahead * CAMERA_BEHIND + Vector3.UP * CAMERA_UP
	_camera.look_at_from_position(eye, body.origin + ahead * CAMERA_AHEAD, Vector3.UP)
