class_name PongSnapshot
extends RefCounted
## One [code]Haptics.pong.get_state()[/code], typed: the ball, both paddles, the hand force
## and the device player's effects. An empty state (no extension) reads as a ball at rest
## at the origin.

## Servo time of the state, seconds.
var time_s: float = 0.0
var ball_position: Vector3 = Vector3.ZERO
var ball_velocity: Vector3 = Vector3.ZERO
var ball_spin: Vector3 = Vector3.ZERO
## The territory the ball is in.
var territory: int = 0
## One entry per seat of the largest court (four); the state fills as many as it has.
var paddle_centers: PackedVector3Array = PackedVector3Array(
	[Vector3.ZERO, Vector3.ZERO, Vector3.ZERO, Vector3.ZERO]
)
var paddle_normals: PackedVector3Array = PackedVector3Array(
	[Vector3.FORWARD, Vector3.BACK, Vector3.LEFT, Vector3.RIGHT]
)
var in_contact: Array[bool] = [false, false, false, false]
## Hand force components (device space, N): contact, spin, effects, total.
var hand_force: Dictionary[String, Vector3] = {}
## The device player's active effects, each {kind, remaining_s}.
var effects: Array[Dictionary] = []
var paddle_contacts: int = 0
var bounces: int = 0


static func from_state(state: Dictionary) -> PongSnapshot:
	var snapshot: PongSnapshot = PongSnapshot.new()
	if state.is_empty():
		return snapshot
	snapshot.time_s = state.get("time_s", 0.0)
	var ball: Dictionary = state.get("ball", {})
	snapshot.ball_position = ball.get("position", Vector3.ZERO)
	snapshot.ball_velocity = ball.get("velocity", Vector3.ZERO)
	snapshot.ball_spin = ball.get("spin", Vector3.ZERO)
	snapshot.territory = state.get("territory", 0)
	var players: Array = state.get("players", [])
	for i: int in mini(players.size(), snapshot.paddle_centers.size()):
		var entry: Dictionary = players[i]
		snapshot.paddle_centers[i] = entry.get("paddle_center", Vector3.ZERO)
		snapshot.paddle_normals[i] = entry.get("normal", Vector3.FORWARD)
		snapshot.in_contact[i] = entry.get("in_contact", false)
	var forces: Dictionary = state.get("hand_force", {})
	for component: String in forces:
		snapshot.hand_force[component] = forces[component]
	var entries: Array = state.get("effects", [])
	snapshot.effects.assign(entries)
	snapshot.paddle_contacts = state.get("paddle_contacts", 0)
	snapshot.bounces = state.get("bounces", 0)
	return snapshot


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
