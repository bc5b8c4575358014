class_name PongRules
extends RefCounted
## Health and the winner. Each player starts with [member start_health] (the paper's
## players had 99) and loses it as the match's events say: a bounce of the ball on the
## floor of one's own territory, a bullet on one's avatar, an opponent's mine stepped on,
## and in beginner mode the ball hitting the target on one's back wall. The first player at
## 0 loses; the match is then over and health changes no more.
## [br]With more than two players ([member players]) a goal is the ball hitting a player's
## back wall anywhere (the target in beginner mode); a player at 0 is out (its territory
## costs nobody any more) and the match ends when one player is left, the winner.

## A player's health changed: [param cause] is one of the [code]CAUSE_*[/code] names.
signal health_changed(player: int, health: int, cause: StringName)
## A player's health reached 0 in a match of more than two: it is out.
signal player_out(player: int)
## One player is left: [param winner] wins.
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
## How many players (2 or 4).
var players: int = 2
## The winner's index, or -1 while the match goes on.
var winner: int = -1

var _health: PackedInt32Array = PackedInt32Array([0, 0])


func _init(p_start_health: int = DEFAULT_START_HEALTH, p_players: int = 2) -> void:
	start_health = maxi(p_start_health, 1)
	players = clampi(p_players, 2, 4)
	reset()


## A new match: full health, no winner.
func reset() -> void:
	_health = PackedInt32Array()
	for player: int in players:
		_health.append(start_health)
	winner = -1


## The match as it stands elsewhere: each player's [param health] (a player who rejoins a
## running network match), within [0, start health]; no winner yet.
func resume(health: PackedInt32Array) -> void:
	for player: int in mini(health.size(), players):
		_health[player] = clampi(health[player], 0, start_health)


## Whether [param player] is out of health (out of the match).
func is_out(player: int) -> bool:
	return _health[player] <= 0


## The players still in, in index order.
func alive() -> Array[int]:
	var left: Array[int] = []
	for player: int in players:
		if not is_out(player):
			left.append(player)
	return left


## The player across from [param player] when still in, else the first one still in.
func opponent_in(player: int) -> int:
	var across: int = PongCourt.opponent_of(player)
	if across < players and not is_out(across):
		return across
	for other: int in alive():
		if other != player:
			return other
	return across


func get_health(player: int) -> int:
	return _health[player]


## Whether a player has won.
func is_over() -> bool:
	return winner >= 0


## [param player] loses the health [param cause] costs (nothing once the match is over).
## Returns the health lost.
func hurt(player: int, cause: StringName) -> int:
	if is_over() or player < 0 or player >= players or is_out(player):
		return 0
	if not DAMAGE.has(cause):
		push_error("PongRules.hurt: unknown cause '%s'." % cause)
		return 0
	var lost: int = mini(DAMAGE[cause], _health[player])
	_health[player] -= lost
	health_changed.emit(player, _health[player], cause)
	if _health[player] == 0:
		var left: Array[int] = alive()
		if players > 2:
			player_out.emit(player)
		if left.size() == 1:
			winner = left[0]
			match_over.emit(winner)
	return lost


## Applies one event of the servo ([method PongServo.drain_events]): a floor bounce costs
## the player whose territory it is in; a back-wall hit costs that wall's owner, within the
## target in [param beginner] mode, anywhere with more than two players (two-player
## matches outside beginner mode score floor bounces only, the paper's rule). Returns the
## player hurt, or -1.
func apply_event(event: PongEvent, court: PongCourt, beginner: bool) -> int:
	match event.type:
		PongServoFacts.PongEventType.FLOOR:
			return event.territory if hurt(event.territory, CAUSE_FLOOR) > 0 else -1
		PongServoFacts.PongEventType.WALL:
			if not beginner and players == 2:
				return -1
			var owner: int = event.back_wall_of if event.back_wall_of < players else -1
			if owner < 0:
				return -1
			if beginner and not court.in_target(event.position, owner):
				return -1
			return owner if hurt(owner, CAUSE_GOAL) > 0 else -1
	return -1
