extends TestSuite
## The base of the suites that play in the test room: a fresh room per test with its
## player, which the test steers itself (not through the haptic device).

const TEST_ROOM := preload("res://tests/support/room.tscn")

var _room: TestRoom = null
var _player: Player = null


func before_each() -> void:
	_room = add_child_autofree(TEST_ROOM.instantiate()) as TestRoom
	_player = _room.get_node(^"Player") as Player
	_player.use_keyboard = false
	(_player.get_node(^"HapticProbe") as HapticProbe).drive_input = false
