extends RefCounted
## Reading the servo events a Pong test collected (the dictionaries of drain_pong_events).


## Whether [param events] hold one of [param type] for [param player].
static func saw(events: Array[Dictionary], type: String, player: int) -> bool:
	for event: Dictionary in events:
		var who: int = event.get("player", -1)
		if str(event.get("type", "")) == type and who == player:
			return true
	return false
