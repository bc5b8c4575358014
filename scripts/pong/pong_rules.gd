class_name PongRules
extends RefCounted
## Health and the winner. Each player starts with [member start_health] (the paper's
## players had 99) and loses it as the match's events say: a bounce of the ball on the
## floor of one's own territory, a bullet on one's avatar, an opponent's mine stepped on,
## and in beginner mode the ball hitting the target on one's back wall. The first player at
## 0 loses; the match is then over and health changes no more.

## A player's health changed: [param cause] is one of the [code]CAUSE_*[/code] names.
signal health_changed(player: int, health: int, cause: StringName)
## A player's health reached 0: the other one, [param winner], wins.
signal match_over(winner: int)

## Health at the start of a match unless the game says otherwise (the paper's 99).
const DEFAULT_START_HEALTH: int = 99
const CAUSE_FLOOR: StringName = &"floor"
const CAUSE_BULLET: StringName = &"bullet"
const CAUSE_MINE: StringName = &"mine"
const CAUSE_GOAL: StringName = &"goal"
## Health lost per cause. A floor bounce costs one point, like a point in Pong; a bullet or
## a mine costs more, as a reward for the risk of placing or aiming it; a beginner-mode
## goal is the whole rally, so it costs the most.
const DAMAGE: Dictionary[StringName, int] = {
	CAUSE_FLOOR: 1, CAUSE_BULLET: 3, CAUSE_MINE: 5, CAUSE_GOAL: 10
}

## Health each player starts with.
var start_health: int = DEFAULT_START_HEALTH
## The winner's index, or -1 while the match goes on.
var winner: int = -1

var _health: PackedInt32Array = PackedInt32Array([0, 0])


func _init(p_start_health: int = DEFAULT_START_HEALTH) -> void:
	start_health = maxi(p_start_health, 1)
	reset()


## A new match: full health, no winner.
func reset() -> void:
	_health = PackedInt32Array([start_health, start_health])
	winner = -1


func get_health(player: int) -> int:
	return _health[player]


## Whether a player has won.
func is_over() -> bool:
	return winner >= 0


## [param player] loses the health [param cause] costs (nothing once the match is over).
## Returns the health lost.
func hurt(player: int, cause: StringName) -> int:
	if is_over() or player < 0 or player > 1:
		return 0
	if not DAMAGE.has(cause):
		push_error("PongRules.hurt: unknown cause '%s'." % cause)
		return 0
	var lost: int = mini(DAMAGE[cause], _health[player])
	_health[player] -= lost
	health_changed.emit(player, _health[player], cause)
	if _health[player] == 0:
		winner = PongCourt.opponent_of(player)
		match_over.emit(winner)
	return lost


## Applies one event of the servo ([code]drain_pong_events()[/code]): a floor bounce costs
## the player whose territory it is in; in [param beginner] mode a back-wall hit within the
## target costs that wall's owner. Returns the player hurt, or -1.
func apply_event(event: Dictionary, court: PongCourt, beginner: bool) -> int:
	match str(event.get("type", "")):
		"floor":
			var territory: int = event.get("territory", -1)
			return territory if hurt(territory, CAUSE_FLOOR) > 0 else -1
		"wall":
			if not beginner:
				return -1
			var position: Vector3 = event.get("position", Vector3.ZERO)
			for player: int in 2:
				if str(event.get("wall", "")) == PongCourt.back_wall_name(player):
					if court.in_target(position) and hurt(player, CAUSE_GOAL) > 0:
						return player
	return -1
