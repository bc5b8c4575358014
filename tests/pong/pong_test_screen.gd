extends RefCounted
## The Pong screen as the scene tests and the bench drive it: no setup screen, stepped by the
## caller (the match does not step on its own, and serves only if [param auto_serve]), in
## [param mode] with [param players] seats and [param health] each. Not yet in the tree: the
## caller adds it.

const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")


static func stepped(
	mode: PongMatch.Mode = PongMatch.Mode.DEMO,
	players: int = 2,
	health: int = 99,
	auto_serve: bool = false
) -> PongScreen:
	var pong: PongScreen = PONG_SCENE.instantiate() as PongScreen
	pong.skip_setup = true
	pong.mode = mode
	pong.players = players
	pong.start_health = health
	pong.stepped = true
	var match_node: PongMatch = pong.get_node(^"Match") as PongMatch
	match_node.auto_serve = auto_serve
	match_node.self_stepping = false
	return pong
