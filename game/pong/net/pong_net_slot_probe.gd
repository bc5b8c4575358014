class_name PongNetSlotProbe
extends RefCounted
## The server's own look at its ENet slots, which Godot does not show: ENet gives a slot to
## every connection request it answers and keeps it through the handshake (about 30 s for a
## request never followed up), and [method ENetConnection.get_peers] lists a peer only once
## it has connected. The probe asks its own server for a connection, from a socket of its
## own on this machine, as any client does (an ENet CONNECT), and reads in ENet's answer (its
## VERIFY_CONNECT) the index of the slot ENet gave it: ENet gives a new request the lowest
## free slot, so every slot below it is held. Then it says goodbye (a DISCONNECT, which frees
## a slot still in the handshake at once, and Godot never hears of it). No answer within
## [constant PATIENCE_S] and [constant PATIENCE_FRAMES] frames: no slot was free.
## [br]The datagrams are ENet 1.3's (lsalzman/enet, include/enet/protocol.h): a header of
## {peer id | flags, sent time}, then commands of {command | flags, channel, reliable
## sequence number, body}, all big-endian.

## [method poll]: nothing to report yet.
const WAITING: int = -1
## [method poll]: no answer; every slot is held (or the request was lost on the way).
const FULL: int = -2
## How long an answer may take, seconds and frames of ours (each frame services ENet once:
## a frame that stalled must not read as a full server).
const PATIENCE_S: float = 1.0
const PATIENCE_FRAMES: int = 3

const _PEER_NONE: int = 0x0FFF
const _FLAG_SENT_TIME: int = 0x8000
const _FLAG_COMPRESSED: int = 0x4000
const _FLAG_ACKNOWLEDGE: int = 0x80
const _COMMAND_MASK: int = 0x0F
const _COMMAND_ACKNOWLEDGE: int = 1
const _COMMAND_CONNECT: int = 2
const _COMMAND_VERIFY_CONNECT: int = 3
const _COMMAND_DISCONNECT: int = 4
const _SESSION_SHIFT: int = 12
# Sizes of the commands a server's first answer holds (ENet's commandSizes).
const _COMMAND_BYTES: Dictionary[int, int] = {_COMMAND_ACKNOWLEDGE: 8, _COMMAND_VERIFY_CONNECT: 44}

var _socket: PacketPeerUDP = PacketPeerUDP.new()
# The request under way (its connect id), or -1; when it left, and the frames since.
var _connect_id: int = -1
var _sent_s: float = 0.0
var _frames: int = 0


## Whether no request is under way.
func idle() -> bool:
	return _connect_id < 0


## Asks ENet at [param address]:[param port] for a connection at [param now_s]; false when the
## socket cannot send.
func send(address: String, port: int, now_s: float) -> bool:
	if not _socket.is_bound() and _socket.bind(0, "*") != OK:
		return false
	while _socket.get_available_packet_count() > 0:
		_socket.get_packet()  # Late answers to an older request.
	if _socket.set_dest_address(address, port) != OK:
		return false
	_connect_id = randi()
	_sent_s = now_s
	_frames = 0
	if _socket.put_packet(connect_datagram(_connect_id, now_s)) != OK:
		_connect_id = -1
		return false
	return true


## Once a frame: the slot ENet gave the request under way (and the probe lets it go), [constant
## FULL], or [constant WAITING].
func poll(now_s: float) -> int:
	if idle():
		return WAITING
	_frames += 1
	while _socket.get_available_packet_count() > 0:
		var verify: Array[int] = verified_slot(_socket.get_packet(), _connect_id)
		if not verify.is_empty():
			_socket.put_packet(disconnect_datagram(verify[0], verify[1]))
			_connect_id = -1
			return verify[0]
	if now_s - _sent_s >= PATIENCE_S and _frames >= PATIENCE_FRAMES:
		_connect_id = -1
		return FULL
	return WAITING


func close() -> void:
	_socket.close()
	_connect_id = -1


## An ENet CONNECT from a client with no peer yet: our peer index 0, any sessions, MTU 1400,
## 32 KiB window, 1 channel, no bandwidth limits, ENet's throttle defaults, [param connect_id]
## and user data 0.
static func connect_datagram(connect_id: int, now_s: float) -> PackedByteArray:
	var out: PackedByteArray = PackedByteArray()
	_u16(out, _FLAG_SENT_TIME | _PEER_NONE)
	_u16(out, int(now_s * 1000.0) & 0xFFFF)
	out.append_array([_FLAG_ACKNOWLEDGE | _COMMAND_CONNECT, 0xFF])
	_u16(out, 1)
	_u16(out, 0)
	out.append_array([0xFF, 0xFF])
	for field: int in [1400, 32768, 1, 0, 0, 5000, 2, 2, connect_id & 0xFFFFFFFF, 0]:
		_u32(out, field)
	return out


## [slot, session] of the VERIFY_CONNECT for [param connect_id] in [param data], or [].
static func verified_slot(data: PackedByteArray, connect_id: int) -> Array[int]:
	if data.size() < 4:
		return []
	var flags: int = _read_u16(data, 0)
	if flags & _FLAG_COMPRESSED:
		return []
	var offset: int = 4 if flags & _FLAG_SENT_TIME else 2
	while offset + 4 <= data.size():
		var kind: int = data[offset] & _COMMAND_MASK
		var size: int = _COMMAND_BYTES.get(kind, 0)
		if size == 0 or offset + size > data.size():
			return []
		if kind == _COMMAND_VERIFY_CONNECT and _read_u32(data, offset + 40) == connect_id:
			return [_read_u16(data, offset + 4), data[offset + 7]]
		offset += size
	return []


## A DISCONNECT from the peer ENet put in [param slot], on [param session] (the session the
## VERIFY_CONNECT told it to send with).
static func disconnect_datagram(slot: int, session: int) -> PackedByteArray:
	var out: PackedByteArray = PackedByteArray()
	_u16(out, (slot & _PEER_NONE) | ((session & 0x3) << _SESSION_SHIFT))
	out.append_array([_COMMAND_DISCONNECT, 0xFF])
	_u16(out, 0)
	_u32(out, 0)
	return out


static func _u16(out: PackedByteArray, value: int) -> void:
	out.append_array([(value >> 8) & 0xFF, value & 0xFF])


static func _u32(out: PackedByteArray, value: int) -> void:
	out.append_array(
		[(value >> 24) & 0xFF, (value >> 16) & 0xFF, (value >> 8) & 0xFF, value & 0xFF]
	)


static func _read_u16(data: PackedByteArray, at: int) -> int:
	return (data[at] << 8) | data[at + 1]


static func _read_u32(data: PackedByteArray, at: int) -> int:
	return (_read_u16(data, at) << 16) | _read_u16(data, at + 2)
