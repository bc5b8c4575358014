class_name PongEffects
extends RefCounted
## The mine effects the game keeps time of, one per player at most (a new mine replaces
## the running effect). For the device player the servo renders the effect on the hand
## (the game only sends the command, and the HUD reads the servo's own countdown); for a
## kinematic player (the computer, the keyboard player) the game applies it to the
## paddle's motion here:
## [br]- slow: the avatar and the paddle move at [constant SLOW_SPEED_FACTOR] of their
## speed (the device's viscous paddle);
## [br]- heavy: the paddle sags by [constant HEAVY_SAG_M] (the device's weight);
## [br]- remote: the paddle is pulled [constant REMOTE_PULL] of the way toward the mirror
## image of the owner's paddle offset (the device's spring to the other player);
## [br]- none: nothing.
## Each ramps in and out over [member ramp_s], like the servo's.

const SLOW_SPEED_FACTOR: float = 0.35
const HEAVY_SAG_M: float = 0.25
const REMOTE_PULL: float = 0.7

## Ramp in and out, seconds (the servo's, from the configuration).
var ramp_s: float = 0.25
## The paddle's reach from its avatar, metres: no effect moves a paddle beyond it, as no
## force moves the device's stylus out of its workspace.
var reach: float = INF

# One slot per seat of the largest court (four players).
var _kind: PackedStringArray = PackedStringArray(["", "", "", ""])
var _remaining: PackedFloat32Array = PackedFloat32Array([0.0, 0.0, 0.0, 0.0])
var _elapsed: PackedFloat32Array = PackedFloat32Array([0.0, 0.0, 0.0, 0.0])
var _owner: PackedInt32Array = PackedInt32Array([-1, -1, -1, -1])


## Starts [param kind] on [param player] for [param duration_s], placed by [param owner].
func start(player: int, kind: String, duration_s: float, owner: int) -> void:
	_kind[player] = kind
	_remaining[player] = duration_s
	_elapsed[player] = 0.0
	_owner[player] = owner


## Ends every effect.
func clear() -> void:
	for player: int in _kind.size():
		_kind[player] = ""
		_remaining[player] = 0.0


## Advances the clocks by [param dt] seconds; an effect whose time is up ends.
func advance(dt: float) -> void:
	for player: int in _kind.size():
		if _kind[player].is_empty():
			continue
		_elapsed[player] += dt
		_remaining[player] -= dt
		if _remaining[player] <= 0.0:
			_kind[player] = ""
			_remaining[player] = 0.0


## The kind running on [param player] ("" when none).
func kind_of(player: int) -> String:
	return _kind[player]


## Seconds left of [param player]'s effect (0 when none).
func remaining(player: int) -> float:
	return _remaining[player]


## [param player]'s effect and the seconds it has left, as the servo reports the device
## player's, or null when none.
func state_of(player: int) -> PongEffectState:
	var index: int = PongServoFacts.PONG_EFFECT_KIND_NAMES.find(_kind[player])
	if index < 0:
		return null
	var state: PongEffectState = PongEffectState.new()
	state.kind = index as PongServoFacts.PongEffectKind
	state.remaining_s = _remaining[player]
	return state


## The player who placed the mine of [param player]'s effect (-1 when none).
func owner_of(player: int) -> int:
	return _owner[player] if not _kind[player].is_empty() else -1


## 0..1: how much of the effect applies now (ramps in and out).
func strength(player: int) -> float:
	if _kind[player].is_empty():
		return 0.0
	if ramp_s <= 0.0:
		return 1.0
	return clampf(minf(_elapsed[player], _remaining[player]) / ramp_s, 0.0, 1.0)


## The speed factor of [param player]'s avatar and paddle (1 without a slow effect).
func speed_factor(player: int) -> float:
	if _kind[player] != "slow":
		return 1.0
	return lerpf(1.0, SLOW_SPEED_FACTOR, strength(player))


## A kinematic paddle offset (world, from the avatar) under [param player]'s effect;
## [param owner_offset] is the effect owner's paddle offset (for remote).
func affect_offset(player: int, offset: Vector3, owner_offset: Vector3) -> Vector3:
	var amount: float = strength(player)
	match _kind[player]:
		"heavy":
			return (offset + Vector3.DOWN * HEAVY_SAG_M * amount).limit_length(reach)
		"remote":
			# The owner's offset in its own device frame, mirrored left-right, then in ours.
			var owner: int = _owner[player]
			var local: Vector3 = (
				PongCourt.side_rotation(owner).inverse() * owner_offset.limit_length(reach)
			)
			local.x = -local.x
			var target: Vector3 = PongCourt.side_rotation(player) * local
			return offset.lerp(target, REMOTE_PULL * amount).limit_length(reach)
	return offset
