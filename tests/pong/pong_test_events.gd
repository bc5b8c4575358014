extends RefCounted
## The servo events of a Pong test: reading those it collected
## ([method PongServo.drain_events], [signal PongMatch.event_seen]) and making the ones it
## hands the rules itself.

const TYPE := PongServoFacts.PongEventType
const SURFACE := PongServoFacts.CourtSurface
## [method count]'s territory for "any".
const ANY_TERRITORY: int = -1


## Whether [param events] hold one of [param type] for [param player].
static func saw(events: Array[PongEvent], type: PongServoFacts.PongEventType, player: int) -> bool:
	for event: PongEvent in events:
		if event.type == type and event.player == player:
			return true
	return false


## The events of [param type] in [param events], oldest first.
static func of_type(
	events: Array[PongEvent], type: PongServoFacts.PongEventType
) -> Array[PongEvent]:
	var out: Array[PongEvent] = []
	for event: PongEvent in events:
		if event.type == type:
			out.append(event)
	return out


## How many of [param events] are of [param type], only those in [param territory] unless
## it is [constant ANY_TERRITORY].
static func count(
	events: Array[PongEvent], type: PongServoFacts.PongEventType, territory: int = ANY_TERRITORY
) -> int:
	var total: int = 0
	for event: PongEvent in of_type(events, type):
		total += 1 if territory == ANY_TERRITORY or event.territory == territory else 0
	return total


## A floor bounce in [param territory].
static func floor_bounce(territory: int) -> PongEvent:
	var event: PongEvent = PongEvent.new()
	event.type = TYPE.FLOOR
	event.territory = territory
	return event


## A bounce off [param wall] at [param position], the goal of [param back_wall_of] (-1: of
## nobody), as the servo reports it.
static func wall_hit(
	wall: PongServoFacts.CourtSurface, back_wall_of: int, position: Vector3 = Vector3.ZERO
) -> PongEvent:
	var event: PongEvent = PongEvent.new()
	event.type = TYPE.WALL
	event.wall = wall
	event.back_wall_of = back_wall_of
	event.position = position
	return event


## [param player]'s paddle starting to touch the ball.
static func paddle_touch(player: int) -> PongEvent:
	var event: PongEvent = PongEvent.new()
	event.type = TYPE.PADDLE
	event.player = player
	return event
