class_name Room3D
extends Node3D
## The 3D level: a walled room with a pool to wade through, crates, and a ramp up to a
## platform where the goal ring is. The [Explorer] carries a [HapticProbe3D]; a camera
## follows it from behind, so forward on the keys or the device is away from the camera.
## Built in code: the scene runs on its own (F6) with nothing but the Haptics autoload.
## [br][br]
## Esc returns to the menu; at the goal, Enter plays again.

## The player reached the goal ring.
signal goal_reached
## The player asked for the menu (Esc).
signal menu_requested
## The player asked to play again (Enter at the goal).
signal restart_requested

## Where the explorer starts.
const START := Vector3(-5.5, 0.6, 4.0)
## Where the goal ring stands, on the platform.
const GOAL := Vector3(5.0, 1.0, -4.0)
## Waypoints from the start to the goal a follower can walk without getting stuck: through
## the pool, past the crates, up the ramp. The game never follows them; test drivers do.
const PATH: Array[Vector3] = [
	Vector3(-3.0, 0.0, 2.0),
	Vector3(-0.5, 0.0, 0.0),
	Vector3(2.0, 0.0, 1.5),
	Vector3(5.0, 0.0, 2.5),
	Vector3(5.0, 0.0, 0.0),
	Vector3(5.0, 0.0, -4.0),
]
## The camera's place behind and above the explorer.
const CAMERA_OFFSET := Vector3(0.0, 6.0, 5.0)

## The avatar.
var explorer: Explorer = null
## Whether the goal was reached.
var finished: bool = false
## Who steers in place of the person (null: the person); set before the room enters the tree.
var pilot: Room3DPilot = null
## Game time since the start, in seconds (stops at the goal).
var elapsed: float = 0.0

var _camera: Camera3D = null
var _status: Label = null
var _build: Room3DBuilder = null


func _ready() -> void:
	_build = Room3DBuilder.new(self)
	_build.room()
	_build.pool(Vector3(-0.5, 0.0, 0.5), Vector3(4.0, 1.2, 4.0))
	for at: Vector3 in [Vector3(1.5, 0.3, 3.5), Vector3(2.4, 0.3, 3.7), Vector3(-4.0, 0.3, -3.5)]:
		_build.crate(at)
	_build.platform_with_ramp(GOAL)
	_build.goal_ring(GOAL).body_entered.connect(_on_goal_body_entered)
	explorer = _build.explorer(START)
	_camera = _build.camera()
	_status = _build.status_label()
	_status.text = "Arrows or the device: walk to the gold ring   ·   Esc: menu"
	if pilot != null:
		explorer.use_keyboard = false
		Haptics.hand_follows_input = false
	_follow_camera()


func _exit_tree() -> void:
	if pilot != null:
		Haptics.hand_follows_input = true
		Haptics.device.set_hand_target(Vector2.ZERO)


func _physics_process(delta: float) -> void:
	if finished:
		explorer.input_vector = Vector3.ZERO
		return
	elapsed += delta
	if pilot != null and not pilot.steer(self, delta):
		explorer.input_vector = Vector3.ZERO
	_follow_camera()


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		menu_requested.emit()
	elif finished and event.is_action_pressed(&"ui_accept"):
		get_viewport().set_input_as_handled()
		restart_requested.emit()


## The explorer's probe.
func probe() -> HapticProbe3D:
	return explorer.get_node(^"HapticProbe3D") as HapticProbe3D


func _follow_camera() -> void:
	_camera.position = explorer.position + CAMERA_OFFSET
	_camera.look_at(explorer.position + Vector3(0.0, 0.5, 0.0))


func _on_goal_body_entered(body: Node3D) -> void:
	if body != explorer or finished:
		return
	finished = true
	_status.text = "Goal in %.1f s!   Enter: play again   ·   Esc: menu" % elapsed
	goal_reached.emit()
