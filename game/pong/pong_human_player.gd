class_name PongHumanPlayer
extends PongController
## A person playing. Two schemes:
## [br][b]Device[/b] (player 0): WASD / arrows / left stick move the avatar; the mouse moves
## the simulated device's hand in x/y, the wheel or R/F (gamepad triggers) in depth; Q/E
## and Z/C (right stick) turn the paddle's normal; with a device the servo places the
## paddle, without one the same hand position moves a kinematic paddle.
## [br][b]Keyboard[/b] (player 1): IJKL move the avatar (screen directions), U/O lower and
## raise the paddle, P swings it forward while held.
## [br]Both: a key each toggles the spin paddle, the gun, fires, places a mine (see
## [constant ACTIONS]).

enum Scheme { DEVICE, KEYBOARD }

## The input actions of each scheme, by role.
const ACTIONS: Dictionary[Scheme, Dictionary] = {
	Scheme.DEVICE:
	{
		"left": &"move_left",
		"right": &"move_right",
		"up": &"move_up",
		"down": &"move_down",
		"spin": &"spin_toggle",
		"gun": &"gun_toggle",
		"fire": &"fire",
		"mine": &"place_mine",
	},
	Scheme.KEYBOARD:
	{
		"left": &"p1_left",
		"right": &"p1_right",
		"up": &"p1_up",
		"down": &"p1_down",
		"spin": &"p1_spin_toggle",
		"gun": &"p1_gun_toggle",
		"fire": &"p1_fire",
		"mine": &"p1_place_mine",
	},
}
const AVATAR_SPEED_M_PER_S: float = 2.4
## How fast the keys turn the paddle, radians per second, and how far.
const TURN_RATE_RAD_PER_S: float = 1.6
const MAX_YAW_RAD: float = 1.0
const MAX_TILT_RAD: float = 1.1
## The paddle's starting tilt up from vertical: a descending ball comes back up.
const REST_TILT_RAD: float = 0.45
## Depth change per wheel notch and per second of R/F, fractions of the workspace radius.
const DEPTH_PER_NOTCH: float = 0.08
const DEPTH_RATE_PER_S: float = 1.5
## Keyboard scheme: the paddle's height change rate and its swing, m/s.
const KEYBOARD_LIFT_M_PER_S: float = 1.2
const KEYBOARD_SWING_M_PER_S: float = 3.0
const KEYBOARD_RETURN_M_PER_S: float = 1.5

var scheme: Scheme = Scheme.DEVICE
## Read the keyboard, mouse and gamepad (tests turn it off and set [member intent]).
var reads_input: bool = true
## The hand in the workspace, fractions of its radius (device space: x right, y up, z
## toward the user).
var hand: Vector3 = Vector3.ZERO
var yaw: float = 0.0
var tilt: float = REST_TILT_RAD

var _court: PongCourt = null
var _reach: float = 0.5
var _workspace_radius: float = 0.0
var _toggles: Dictionary[String, bool] = {}
var _last_offset: Vector3 = Vector3.ZERO
var _lift: float = 0.0
var _swing: float = 0.0


## [param reach]: the paddle's reach from the avatar, metres; [param workspace_radius]: the
## device's, metres (0 without a device).
func _init(
	p_player: int, p_scheme: Scheme, court: PongCourt, reach: float, workspace_radius: float
) -> void:
	player = p_player
	scheme = p_scheme
	_court = court
	_reach = reach
	_workspace_radius = workspace_radius
	intent.avatar = court.clamp_avatar(player, court.toward_back_wall(player, 0.6))
	intent.normal = _normal()


func handle_input(event: InputEvent, viewport_size: Vector2) -> void:
	if not reads_input:
		return
	for role: String in ["spin", "gun", "fire", "mine"]:
		if event.is_action_pressed(_action(role), false, true):
			_toggles[role] = true
	if scheme != Scheme.DEVICE:
		return
	if event is InputEventMouseMotion and viewport_size.y > 0.0:
		# A quarter of the window's height from its centre is the workspace's edge.
		var offset: Vector2 = (event as InputEventMouseMotion).position - viewport_size * 0.5
		var planar: Vector2 = (offset / (viewport_size.y * 0.25)).limit_length(1.0)
		hand = Vector3(planar.x, -planar.y, hand.z)
	elif event is InputEventMouseButton and (event as InputEventMouseButton).pressed:
		var button: MouseButton = (event as InputEventMouseButton).button_index
		if button == MOUSE_BUTTON_WHEEL_UP:
			hand.z -= DEPTH_PER_NOTCH
		elif button == MOUSE_BUTTON_WHEEL_DOWN:
			hand.z += DEPTH_PER_NOTCH
		hand.z = clampf(hand.z, -1.0, 1.0)


func update(_now: float, dt: float, _snapshot: PongState, _opponent: Vector3) -> PongIntent:
	intent.fire = _take("fire")
	intent.place_mine = _take("mine")
	if _take("spin"):
		intent.spin = not intent.spin
	if _take("gun"):
		intent.gun = not intent.gun
	if not reads_input:
		return intent
	var walk: Vector2 = Input.get_vector(
		_action("left"), _action("right"), _action("up"), _action("down")
	)
	var before: Vector3 = intent.avatar
	var step: Vector3 = Vector3(walk.x, 0.0, walk.y) * AVATAR_SPEED_M_PER_S * speed_factor * dt
	if scheme == Scheme.DEVICE:
		# The camera sits behind the device player's own side (a network game's seat).
		step = PongCourt.side_rotation(player) * step
	intent.avatar = _court.clamp_avatar(player, intent.avatar + step)
	var offset: Vector3 = _device_offset(dt) if scheme == Scheme.DEVICE else _keyboard_offset(dt)
	intent.normal = _normal()
	if kinematic:
		intent.paddle_offset = offset
		intent.paddle_velocity = (
			((intent.avatar + offset) - (before + _last_offset)) / maxf(dt, 1e-6)
		)
	_last_offset = offset
	return intent


func _action(role: String) -> StringName:
	var action: StringName = ACTIONS[scheme][role]
	return action


func _take(role: String) -> bool:
	var pressed: bool = _toggles.get(role, false)
	_toggles[role] = false
	return pressed


# The device scheme: turns the paddle, moves the hand in depth, and either moves the
# simulated device's hand there (the servo places the paddle) or returns the kinematic
# offset the same hand position stands for.
func _device_offset(dt: float) -> Vector3:
	yaw = clampf(
		yaw + Input.get_axis(&"paddle_yaw_right", &"paddle_yaw_left") * TURN_RATE_RAD_PER_S * dt,
		-MAX_YAW_RAD,
		MAX_YAW_RAD
	)
	tilt = clampf(
		tilt + Input.get_axis(&"paddle_tilt_down", &"paddle_tilt_up") * TURN_RATE_RAD_PER_S * dt,
		-MAX_TILT_RAD,
		MAX_TILT_RAD
	)
	var depth: float = Input.get_axis(&"paddle_push", &"paddle_pull") * DEPTH_RATE_PER_S * dt
	hand.z = clampf(hand.z + depth, -1.0, 1.0)
	hand = hand.limit_length(1.0)
	if not kinematic:
		# A physical device is moved by the hand itself.
		if _workspace_radius > 0.0 and Haptics.device.is_simulated():
			PongServo.shared().set_hand_target_3d(hand * _workspace_radius)
		return Vector3.ZERO
	return PongCourt.side_rotation(player) * hand * _reach


# The keyboard scheme: U/O lift, P swings forward while held and the paddle comes back
# when released.
func _keyboard_offset(dt: float) -> Vector3:
	var lift: float = Input.get_axis(&"p1_paddle_down", &"p1_paddle_up")
	_lift = clampf(_lift + lift * KEYBOARD_LIFT_M_PER_S * dt, -_reach * 0.8, _reach * 0.8)
	if Input.is_action_pressed(&"p1_swing"):
		_swing = minf(_swing + KEYBOARD_SWING_M_PER_S * dt, _reach * 0.8)
	else:
		_swing = maxf(_swing - KEYBOARD_RETURN_M_PER_S * dt, -_reach * 0.3)
	return Vector3(0.0, _lift, 0.0) + PongCourt.forward(player) * _swing


func _normal() -> Vector3:
	var local: Vector3 = Basis(Vector3.UP, yaw) * Basis(Vector3.RIGHT, tilt) * Vector3.FORWARD
	return PongCourt.side_rotation(player) * local
