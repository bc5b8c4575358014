class_name PongNetFlood
extends RefCounted
## Notices a flood of connection requests on a server (the dedicated one or a player's host)
## and says so once: one line when it starts, one when it is over. ENet gives every request
## a slot for about 30 s, whether or not the requester ever answers, and a server has
## [constant PongNetProtocol.ENET_SLOTS] of them: a flood that outpaces their expiry locks
## new players out, and Godot shows none of those half-open slots. So once a second the
## server asks its own ENet how many slots are held ([PongNetSlotProbe]), less the peers Godot
## knows; [constant FLOOD_SLOTS] or more held by strangers is a flood. It is over once no
## reading of the last [constant QUIET_S] (longer than ENet keeps a slot) showed more than
## [constant QUIET_SLOTS].
## [br]ENet frees a slot in the handshake only when the requester says goodbye or the 30 s
## pass; a script cannot. But a new ENet host on the same port starts with every slot free:
## while nobody is connected (nobody to lose: a player's host waiting for its guests, a
## dedicated server waiting for players) and strangers hold [constant RENEW_SHARE] of the
## slots, the server opens a new one ([method frame]). A player whose request the old host
## had taken repeats it (ENet does, within a second) and the new host answers. With somebody
## connected the slots must hold: 4095 hold a flood of 130 requests a second, and the kernel's
## guard the rest (docs/pong-networking.md, "Floods").

## Seconds between two looks.
const PROBE_PERIOD_S: float = 1.0
## Slots held by requests that never finished the handshake that make a flood: honest
## clients finish it within a few round trips, and a lossy path may keep one or two waiting.
const FLOOD_SLOTS: int = 16
## At most this many, over [constant QUIET_S], and the flood is over.
const QUIET_SLOTS: int = 4
const QUIET_S: float = 40.0
## Requests in a row that ENet must leave unanswered before that reads as every slot held (one
## may be lost, or wait behind a long frame).
const UNANSWERED_IN_A_ROW: int = 2
## The share of the slots strangers may hold before a server nobody is connected to opens a
## new ENet host: at 200 requests a second, every 10 s, and a guest who stays a while still
## leaves time for the next renewal before the slots fill.
const RENEW_SHARE: float = 0.5
const START_LINE: String = "PongNet: a flood of connection requests"
const OVER_LINE: String = "PongNet: the flood of connection requests is over"

## Whether a flood is on now.
var flooding: bool = false
## The most slots held by strangers in this flood.
var peak: int = 0
## New ENet hosts opened in this flood.
var renewals: int = 0
## The server's port.
var port: int = 0

var _probe: PongNetSlotProbe = PongNetSlotProbe.new()
var _address: String = "127.0.0.1"
var _bind_ip: String = "*"
var _slots: int = 0
var _renew: bool = false
var _next_probe_s: float = 0.0
var _since_s: float = 0.0
var _unanswered: int = 0
# The looks of the last QUIET_S: when (s), and the slots strangers held.
var _times: PackedFloat64Array = PackedFloat64Array()
var _held: PackedInt32Array = PackedInt32Array()


## Watches the server on [param port] with [param slots] ENet slots, bound to [param bind_ip]
## ("*": every address; it is reached on this machine's loopback).
func _init(bind_ip: String, p_port: int, slots: int) -> void:
	_address = "127.0.0.1" if bind_ip == "*" or bind_ip.is_empty() else bind_ip
	_bind_ip = bind_ip
	port = p_port
	_slots = slots


## Once a frame of the server [param enet] under [param api]: looks at its slots now and
## then, prints the line the flood's start or end calls for, and returns the peer to go on
## with: [param enet], or a new one on the same port that [param api] now uses, or null when
## none could be opened.
func frame(enet: ENetMultiplayerPeer, api: SceneMultiplayer) -> ENetMultiplayerPeer:
	if enet == null or enet.host == null:
		return enet
	var now: float = PongNetPulse.now_s()
	var known: int = enet.host.get_peers().size()
	var reading: int = _probe.poll(now)
	if reading != PongNetSlotProbe.WAITING:
		var full: bool = reading == PongNetSlotProbe.FULL
		_unanswered = _unanswered + 1 if full else 0
		var held: int = _slots if full else reading
		var line: String = ""
		if not full or _unanswered >= UNANSWERED_IN_A_ROW:
			line = note(now, held - known, full)
			_renew = known == 0 and (held - known) >= int(RENEW_SHARE * _slots)
		if not line.is_empty():
			printerr(line)
	if _renew:
		_renew = false
		return _renewed(enet, api)
	if _probe.idle() and now >= _next_probe_s:
		_next_probe_s = now + PROBE_PERIOD_S
		_probe.send(_address, port, now)
	return enet


## [param strangers] slots are held by requests Godot does not know of at [param now_s]
## ([param full]: ENet gave the probe no slot); returns the line to log, or "".
func note(now_s: float, strangers: int, full: bool = false) -> String:
	strangers = clampi(strangers, 0, _slots)
	_times.append(now_s)
	_held.append(strangers)
	while _times[0] < now_s - QUIET_S:
		_times.remove_at(0)
		_held.remove_at(0)
	if not flooding:
		if strangers < FLOOD_SLOTS:
			return ""
		flooding = true
		peak = strangers
		_since_s = now_s
		var answer: String = ": ENet gave no slot to a request of ours" if full else ""
		return (
			(
				"%s: %d of %d ENet slots held by requests that never finished the handshake"
				+ " (ENet frees each after about 30 s)%s; see docs/pong-networking.md, Floods"
			)
			% [START_LINE, strangers, _slots, answer]
		)
	peak = maxi(peak, strangers)
	if now_s - _since_s < QUIET_S:
		return ""
	for held: int in _held:
		if held > QUIET_SLOTS:
			return ""
	flooding = false
	var line: String = (
		"%s (at most %d slots held, %d new ENet hosts; %.0f s)"
		% [OVER_LINE, peak, renewals, now_s - _since_s]
	)
	renewals = 0
	return line


func close() -> void:
	_probe.close()


# A new ENet host on [param enet]'s port for [param api] (nobody is connected to the old one).
func _renewed(enet: ENetMultiplayerPeer, api: SceneMultiplayer) -> ENetMultiplayerPeer:
	enet.close()
	var fresh: ENetMultiplayerPeer = ENetMultiplayerPeer.new()
	fresh.set_bind_ip(_bind_ip)
	if fresh.create_server(port, _slots) != OK:
		return null
	api.multiplayer_peer = fresh
	renewals += 1
	_times.clear()
	_held.clear()
	_probe.close()  # Its request went to the old host.
	return fresh
