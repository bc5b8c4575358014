class_name PongHandFeedback
extends RefCounted
## What the weapons make the player at the device feel, as the servo's effects on the hand:
## a bullet's hit, a mine's rumble and its effect, the gun's recoil. Strengths and
## durations are the court's ([code]pong[/code] configuration).

## Peak of a mine's rumble on the hand, newtons.
const MINE_RUMBLE_N: float = 1.2
## How long a mine's rumble decays, seconds.
const MINE_RUMBLE_DECAY_S: float = 0.35

var court: PongCourt = null


func _init(p_court: PongCourt) -> void:
	court = p_court


## A bullet hit [param player] flying along [param direction] (world).
func hit(player: int, direction: Vector3) -> void:
	PongServo.shared().apply_effect(
		player, "hit", court.settings.hit_force_n, court.settings.hit_duration_s, direction
	)


## [param player] stepped on a [param kind] mine of [param owner]'s: a rumble, then the
## mine's effect for [param duration_s] ("none": the rumble only).
func mine(player: int, kind: String, duration_s: float, owner: int) -> void:
	PongServo.shared().rumble(MINE_RUMBLE_N, MINE_RUMBLE_DECAY_S)
	if kind != "none":
		PongServo.shared().apply_effect(
			player, kind, _magnitude(kind), duration_s, Vector3.ZERO, owner
		)


## [param player] fired along [param axis]: the gun kicks back.
func recoil(player: int, axis: Vector3) -> void:
	PongServo.shared().apply_effect(
		player,
		"recoil",
		court.settings.recoil_force_n,
		court.settings.recoil_duration_s,
		-axis.normalized()
	)


# The slow paddle's viscous force is uncapped (a cap of 0 would silence it).
func _magnitude(kind: String) -> float:
	match kind:
		"heavy":
			return court.settings.heavy_force_n
		"remote":
			return court.settings.remote_max_force_n
	return PongServo.DEFAULT_STRENGTH
