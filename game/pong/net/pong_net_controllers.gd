class_name PongNetControllers
extends RefCounted
## Who drives each seat of a network match on this peer: its own player (the device, the
## mouse, or the computer on an autopilot peer), the computer for the seats the server plays,
## or the network ([PongNetRemotePlayer]) for every seat another peer owns.


## Sets the controller of [param seat] in [param play]'s match on peer [param me];
## [param mine]: the lobby gave this peer's player that seat; [param autopilot]: the computer
## plays for this peer's player; [param factory] (Callable(seat, match) -> PongController or
## null) may choose this peer's own controller (tests).
static func assign(
	play: PongNetPlay, seat: int, me: int, mine: bool, autopilot: bool, factory: Callable
) -> void:
	var match_node: PongMatch = play.match_node
	var current: PongController = match_node.controllers[seat]
	var seats_here: PackedInt32Array = play.local_seats
	if play.authority.owner_of(seat) != me:
		if match_node.local_player == seat:
			match_node.local_player = -1  # No device drives a seat the network moves.
		if not current is PongNetRemotePlayer:
			var remote: PongNetRemotePlayer = PongNetRemotePlayer.new(seat)
			remote.intent = current.intent
			match_node.controllers[seat] = remote
		if seats_here.has(seat):
			seats_here.remove_at(seats_here.find(seat))
		return
	if not seats_here.has(seat):
		seats_here.append(seat)
	if mine and factory.is_valid():
		var made: PongController = factory.call(seat, match_node)
		if made != null:
			match_node.controllers[seat] = made
			return
	if current is PongAi and (autopilot or not mine):
		return
	if mine and not autopilot:
		_seat_person(seat, match_node)
		return
	var ai: PongAi = PongAi.new(seat, match_node.court, match_node.reach, seat + 1)
	ai.intent = current.intent
	match_node.controllers[seat] = ai


# This peer's player drives [param seat] as in a match on this machine: the device scheme,
# the device's own paddle (felt in the servo) when one is usable, else the mouse's kinematic
# one.
static func _seat_person(seat: int, match_node: PongMatch) -> void:
	var device: bool = PongServoLink.new().device_usable()
	match_node.local_player = seat if device else -1
	var current: PongController = match_node.controllers[seat]
	if current is PongHumanPlayer and current.player == seat:
		current.kinematic = not device
		return
	var radius: float = Haptics.device.get_workspace_radius()
	var human: PongHumanPlayer = PongHumanPlayer.new(
		seat, PongHumanPlayer.Scheme.DEVICE, match_node.court, match_node.reach, radius
	)
	human.kinematic = not device
	match_node.controllers[seat] = human
