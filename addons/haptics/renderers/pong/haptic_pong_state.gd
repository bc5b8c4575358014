class_name HapticPongState
extends RefCounted
## The Pong renderer's newest state ([code]Haptics.pong.get_state()[/code]), typed: the
## ball, the paddles, the hand force and the device player's effects. Without the extension
## it reads as a ball at rest at the origin. World vectors in metres (y up); hand forces in
## device space, newtons.

## Servo time of the state, seconds.
var time_s: float = 0.0
var ball_position: Vector3 = Vector3.ZERO
var ball_velocity: Vector3 = Vector3.ZERO
var ball_spin: Vector3 = Vector3.ZERO
## What a network correction still has to blend in (world metres): the corrected ball is at
## [member ball_position] + this ([method HapticsPong.correct_ball]).
var ball_correction: Vector3 = Vector3.ZERO
## The most a correction has moved the ball in one servo tick this session, metres.
var ball_correction_step_max: float = 0.0
## The territory the (corrected) ball is in.
var territory: int = 0
## How many players' paddles the state holds (the court's seats: 2 or 4).
var players: int = 0
## One entry per seat of the largest court (four); the state fills as many as it has.
var paddle_centers: PackedVector3Array = PackedVector3Array(
	[Vector3.ZERO, Vector3.ZERO, Vector3.ZERO, Vector3.ZERO]
)
var paddle_normals: PackedVector3Array = PackedVector3Array(
	[Vector3.FORWARD, Vector3.BACK, Vector3.LEFT, Vector3.RIGHT]
)
## The paddles' centre velocities, world m/s (the device paddle's: its avatar's plus the
## stylus's times the workspace scale).
var paddle_velocities: PackedVector3Array = PackedVector3Array(
	[Vector3.ZERO, Vector3.ZERO, Vector3.ZERO, Vector3.ZERO]
)
var in_contact: Array[bool] = [false, false, false, false]
## Hand force components (device space, N): contact, spin, effects, total.
var hand_force: Dictionary[String, Vector3] = {}
## The device player's active effects, each {kind, remaining_s}.
var effects: Array[Dictionary] = []
var paddle_contacts: int = 0
var bounces: int = 0
## Events the servo dropped because nobody drained them in time.
var events_dropped: int = 0
## The work the remote-operation mine's coupling has done on the hand, joules (the
## servo's count, every tick).
var remote_work_j: float = 0.0


## Reads the dictionary [code]HapticsServer.get_pong_state[/code] returns (empty: no
## extension).
static func from_dictionary(state: Dictionary) -> HapticPongState:
	var out: HapticPongState = HapticPongState.new()
	if state.is_empty():
		return out
	out.time_s = state.get("time_s", 0.0)
	var ball: Dictionary = state.get("ball", {})
	out.ball_position = ball.get("position", Vector3.ZERO)
	out.ball_velocity = ball.get("velocity", Vector3.ZERO)
	out.ball_spin = ball.get("spin", Vector3.ZERO)
	out.ball_correction = ball.get("correction", Vector3.ZERO)
	out.ball_correction_step_max = ball.get("correction_step_max", 0.0)
	out.territory = state.get("territory", 0)
	var paddles: Array = state.get("players", [])
	out.players = paddles.size()
	for i: int in mini(paddles.size(), out.paddle_centers.size()):
		var entry: Dictionary = paddles[i]
		out.paddle_centers[i] = entry.get("paddle_center", Vector3.ZERO)
		out.paddle_normals[i] = entry.get("normal", Vector3.FORWARD)
		out.paddle_velocities[i] = entry.get("paddle_velocity", Vector3.ZERO)
		out.in_contact[i] = entry.get("in_contact", false)
	var forces: Dictionary = state.get("hand_force", {})
	for component: String in forces:
		out.hand_force[component] = forces[component]
	var entries: Array = state.get("effects", [])
	out.effects.assign(entries)
	out.paddle_contacts = state.get("paddle_contacts", 0)
	out.bounces = state.get("bounces", 0)
	out.events_dropped = state.get("events_dropped", 0)
	out.remote_work_j = state.get("remote_work_j", 0.0)
	return out


## The total hand force (device space, N).
func total_force() -> Vector3:
	return force_of("total")


## One hand force component (device space, N): contact, spin, effects or total.
func force_of(component: String) -> Vector3:
	return hand_force.get(component, Vector3.ZERO)


## The device player's effect of [param kind] as {kind, remaining_s}, or empty.
func effect(kind: String) -> Dictionary:
	for entry: Dictionary in effects:
		if str(entry.get("kind", "")) == kind:
			return entry
	return {}
