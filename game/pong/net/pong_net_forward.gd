class_name PongNetForward
extends RefCounted
## A message one client sent to every peer, as the server forwards it to the other clients
## once the node that owns its state accepted it: [constant ID], the client's peer id, then
## the message's own packet. Clients reach each other only this way (Godot's own relay,
## [member SceneMultiplayer.server_relay], is off: it relayed everything, refused or not).

## The first four bytes of a forward (no message layout id is this: test_net_router).
const ID: int = 0x46575244
const HEADER_BYTES: int = 8


## [param packet], sent by [param origin], as the server forwards it.
static func wrap(origin: int, packet: PackedByteArray) -> PackedByteArray:
	var out: PackedByteArray = PackedByteArray()
	out.resize(HEADER_BYTES)
	out.encode_u32(0, ID)
	out.encode_u32(4, origin)
	out.append_array(packet)
	return out


## Whether [param packet] is a forward.
static func owns(packet: PackedByteArray) -> bool:
	return packet.size() >= HEADER_BYTES and packet.decode_u32(0) == ID


## The peer id of the client that sent the forwarded message.
static func origin_of(packet: PackedByteArray) -> int:
	return packet.decode_u32(4)


## The forwarded message's own packet.
static func inner(packet: PackedByteArray) -> PackedByteArray:
	return packet.slice(HEADER_BYTES)
