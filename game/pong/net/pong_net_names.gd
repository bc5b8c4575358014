class_name PongNetNames
extends RefCounted
## The players' names in a network game: the lobby keeps each one distinct, and the match's
## HUD names every seat by who drives it.


## The computer's name for [param seat] of a court of [param seats].
static func computer(seat: int, seats: int) -> String:
	return "Computer" if seats == 2 else "Computer %d" % (seat + 1)


## How the HUD names [param seat] of a court of [param seats], driven by [param seat_owner],
## on the peer [param me]: its player's name from [param players] (the lobby: peer id ->
## {name, seat, ready}), marked as ours on our own seat, or the computer's.
static func seat_title(
	players: Dictionary[int, Dictionary], seats: int, seat: int, seat_owner: int, me: int
) -> String:
	var entry: Dictionary = players.get(seat_owner, {})
	if entry.get("seat", -1) != seat:
		# A player still in the lobby on this seat is cut off: the computer plays it meanwhile.
		for peer: int in players:
			if peer != seat_owner and players[peer].get("seat", -1) == seat:
				return "%s (away)" % players[peer]["name"]
		return computer(seat, seats)
	var title: String = entry["name"]
	return "%s (you)" % title if seat_owner == me else title


## [param wanted] (trimmed), or with a number after it when a player in [param players] has
## that name already (two players who kept the default name).
static func unique(wanted: String, players: Dictionary[int, Dictionary]) -> String:
	var taken: Array[String] = []
	for entry: Dictionary in players.values():
		taken.append(entry["name"])
	var base: String = wanted.strip_edges()
	var name: String = base
	var number: int = 2
	while taken.has(name):
		var suffix: String = " %d" % number
		name = base.left(PongNetProtocol.MAX_NAME_LENGTH - suffix.length()) + suffix
		number += 1
	return name
