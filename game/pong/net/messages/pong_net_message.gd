class_name PongNetMessage
extends HapticsValue
## A message networked Pong's peers send each other: a value of
## [code]game/pong/net/pong_net_messages.schema.toml[/code], which the generator writes as a
## subclass with typed properties, [code]encode()[/code], a static [code]decode()[/code] that
## checks every field, and these facts of how it travels and who sends and takes it, each
## defined once in the schema. It travels as a raw packet ([method SceneMultiplayer.send_bytes])
## that [PongNetRouter] sends, and decodes and checks by its layout id before the node that
## owns its state sees it.


## Words for people: what this message is (log lines, counts).
func label() -> String:
	return ""


## The channel it travels on.
func channel() -> int:
	return 0


## How it travels.
func transfer_mode() -> MultiplayerPeer.TransferMode:
	return MultiplayerPeer.TRANSFER_MODE_RELIABLE


## Whether only the server sends it (from any other peer it is a bad message).
func from_server() -> bool:
	return false


## Whether only the server takes it (on any other peer it is a bad message).
func to_server() -> bool:
	return false
