class_name PongNetProtocol
extends RefCounted
## The wire facts of networked Haptic Battle Pong, defined once, and the checks every
## received message passes before it touches the game. A message that fails a check is
## dropped with one log line naming the sender and the reason; the game goes on.
##
## Channels (ENet, through SceneMultiplayer's transfer_channel): the ball state stream
## (unreliable) and the pose stream (unreliable_ordered) each get their own channel so they
## never queue behind reliable traffic; lobby, hand-offs and rules share one reliable channel.

## Sent and compared at connect (auth): peers of another protocol version are refused.
const VERSION: String = "hbp-net-3"
const DEFAULT_PORT: int = 7420
## The client's first message (its hello) goes on the channel of the version check. Godot
## 4.6 admits a client once each side has sent the other its "auth complete" on channel 0,
## and drops (with an engine error) anything else the client sends before its own "complete"
## has arrived: when that packet was lost and ENet was resending it, a hello on another
## channel overtook it and was thrown away, and the client never joined (seen in CI and on
## lossy paths: docs/pong-networking.md). On channel 0 ENet delivers it after the "complete".
const CHANNEL_HANDSHAKE: int = 0
## The ball stream: unreliable and unordered (ENet's unsequenced), so a state that arrives
## after a newer one still reaches the follower's jitter buffer ([PongNetBallBuffer]); on an
## unreliable_ordered channel ENet drops it, two thirds of the states on a path that reorders.
const CHANNEL_BALL: int = 1
const CHANNEL_POSE: int = 2
const CHANNEL_RELIABLE: int = 3
## The heartbeat's channel (raw packets, unreliable): nothing queues in front of it.
const CHANNEL_BEAT: int = 4
## Seats (territories) a match may have.
const MAX_SEATS: int = 4
## The courts a match can have: two players, or four on a square court.
const SEAT_COUNTS: Array[int] = [2, MAX_SEATS]
const MAX_NAME_LENGTH: int = 24
## Longest auth payload accepted, bytes (a version string).
const MAX_AUTH_BYTES: int = 64
## How far outside the court a received position may lie (a ball state extrapolated by the
## sender, a paddle at full reach), metres.
const POSITION_MARGIN_M: float = 1.0
## Received speeds may exceed the servo's caps by this factor (the sender's extrapolation).
const SPEED_MARGIN: float = 1.5
## Ball stream rate the master keeps at least, Hz (it sends on each new servo state).
const MIN_STREAM_HZ: float = 60.0
## Transfer kinds, in the order ties would be broken (the server sequences them, so ties
## never happen on the wire; the rank is for the log).
const TRANSFER_SERVE: int = 0
const TRANSFER_HANDOFF: int = 1
const TRANSFER_TAKEOVER: int = 2
const TRANSFER_NAMES: Array[String] = ["serve", "handoff", "takeover"]
## What a weapon hurt names as its cause (the rules' causes a weapon has).
const WEAPON_CAUSES: Array[String] = ["bullet", "mine"]
## Highest bullet number a seat may send (a shot every 0.4 s: a few million years).
const MAX_WEAPON_ID: int = 1 << 30
## A seat's shots are at least its cooldown apart in its servo's time; this share of it is
## accepted (the firer counts the cooldown in game time, which a real-time game's frames
## round).
const COOLDOWN_SHARE: float = 0.75
## How far off the floor a received mine may lie, metres.
const FLOOR_TOLERANCE_M: float = 0.01

## ENet timeouts on every peer (docs/networking.md, "ENet's timeouts and how a dead peer is
## noticed"). ENet drops a peer when a reliable packet has been sent
## log2(limit) + 1 times unacknowledged and the minimum has passed, or, checked only when a
## try times out, when it has waited the hard cap. It doubles the wait after each try, so
## the fifth try times out 1 + 2 + 4 + 8 + 16 = 31 retransmission timeouts (RTO, a round
## trip plus four deviations) after the first send, the sixth 63. Five tries on every path:
## with four (a limit of 8) a 5 %-loss path (each try fails about 10 % of the time, one leg
## or the other) lost one packet in ten thousand and a lossy match now and then ended live;
## with five it is one in 100 000. The limit (ENet's default 32) would allow six, so the cap
## decides: 16 RTOs is past the fourth timeout (15) and before the fifth (31). A cap growing
## with the round trip in milliseconds instead let a LAN wait for the sixth timeout
## (docs/pong-networking.md). Game-time values: the cap also bounds how long a frame may
## stall (the longest frame of a four-peer match on two cores), hence the floor.
const TIMEOUT_LIMIT: int = 32
const TIMEOUT_MIN_MS: int = 500
## The cap in retransmission timeouts, its floor and ceiling, ms.
const TIMEOUT_RTOS: float = 16.0
const TIMEOUT_MAX_MS: int = 900
const TIMEOUT_CEILING_MS: int = 8000
## A client connecting to nobody gives up after a few seconds (docs/networking.md, "ENet's
## timeouts and how a dead peer is noticed"); a 3 s cap, so that a lossy path does not fail
## the handshake.
const CONNECT_TIMEOUT_MIN_MS: int = 500
const CONNECT_TIMEOUT_MAX_MS: int = 3000
## ENet's packet throttle drops unreliable packets at the sender whenever a round trip
## comes in above the last one by twice its variance, which a jittery path does all the
## time: the ball and pose streams (a few kB/s) lost much of their states to it with a little
## jitter (docs/pong-networking.md). A deceleration of 0 keeps the throttle open; reliable
## traffic is not throttled either way (ENet's defaults: 5000 ms, 2, 2).
const THROTTLE_INTERVAL_MS: int = 5000
const THROTTLE_ACCELERATION: int = 2
const THROTTLE_DECELERATION: int = 0
## Seconds a connected peer has to pass the version check. The exchange starts from ENet's
## guess of a 500 ms round trip and doubles its wait after each lost try, so on a slow lossy
## path it takes several seconds: Godot's default of 3 s refused most connections on a slow,
## lossy path (docs/pong-networking.md). It only bounds how long a silent peer holds a slot.
const AUTH_TIMEOUT_S: float = 15.0
## Seconds a peer we count as connected has for its first beat. Each side of the handshake
## ends when the other's last message arrives, a reliable packet ENet resends with doubling
## waits, so the two sides may count each other connected far apart: on a slow lossy path a
## host dropped a client soon after it joined, the client still awaiting the host's message,
## unable to beat. Until a first beat the handshake's bound holds.
const FIRST_BEAT_TIMEOUT_S: float = AUTH_TIMEOUT_S

## The heartbeat: every connected pair sends each other a one-byte raw packet this often, and
## drops the other when nothing has come from it for [method heartbeat_timeout_s]. It does
## not wait for ENet, which notices a dead peer only when a reliable packet goes unanswered
## for its whole retransmission schedule (a client killed with nothing reliable in flight
## went unnoticed for many seconds: docs/pong-networking.md).
const HEARTBEAT_HZ: float = 5.0
## Beats in a row a live peer may lose before it is dropped (5 % loss per leg: four in a
## row once in 160 000 windows).
const HEARTBEAT_MISSES: int = 4
## Bounds of the silence that drops a peer, seconds. The floor covers the longest frame of a
## four-peer match on two cores several times over; the ceiling is the promise.
const HEARTBEAT_TIMEOUT_MIN_S: float = 1.0
const HEARTBEAT_TIMEOUT_MAX_S: float = 3.0
## Raw packets (SceneMultiplayer.send_bytes) start with their kind: a heartbeat, the reason
## the server refuses a client (UTF-8 after the kind byte), or a peer's word that it is
## about to stall (it loads a match's court: over a second of silence with four peers on two
## busy cores), sent reliably on the heartbeat's channel, after which its silence may last
## the ceiling until its next beat.
const PACKET_BEAT: int = 1
const PACKET_REFUSAL: int = 2
const PACKET_STALL: int = 3
## Longest refusal reason sent or taken, bytes.
const MAX_REFUSAL_BYTES: int = 200

## ENet peer slots of a server. ENet keeps a peer for every CONNECT datagram it answers
## until the handshake completes or about 30 s pass, and Godot shows no such half-open peer
## to a script (ENetConnection.get_peers() lists a peer only once it has connected), so
## slots are what a flood of crafted CONNECTs uses up: six slots let 12 datagrams lock the
## players out for 30 s. With 1024 a flood must keep up 34 datagrams a second. An empty slot
## costs a few hundred bytes and next to nothing per frame (docs/pong-networking.md, "The
## lobby").
const ENET_SLOTS: int = 1024
## Connections from one address that have connected at ENet's level but not passed the
## version check: more are not taken (the oldest is dropped), so one address cannot hold
## the lobby's attention. A household behind one NAT joins with up to a seat each.
const HALF_OPEN_PER_ADDRESS: int = MAX_SEATS

## Bad messages (malformed, or impossible such as a forged hurt) a peer may send: the first
## is logged, the rest are counted, and the server disconnects a peer that reaches this
## many. An honest peer sends none (races of the authority are not counted).
const MISBEHAVIOUR_BUDGET: int = 16


## Why the arguments of an RPC ([param args], taken as a variadic list so that the engine
## never fails a call for its count) are not [param count] of them, or "".
static func check_arity(args: Array, count: int) -> String:
	if args.size() != count:
		return "%d arguments, not %d" % [args.size(), count]
	return ""


## Why [param value] is not a finite [Vector3] within [param limit] of the origin along
## each axis ([param limit] per component), or "" when it is.
static func check_vector(value: Variant, limit: Vector3, what: String) -> String:
	if typeof(value) != TYPE_VECTOR3:
		return "%s is a %s, not a Vector3" % [what, type_string(typeof(value))]
	var v: Vector3 = value
	if not v.is_finite():
		return "%s is not finite" % what
	if absf(v.x) > limit.x or absf(v.y) > limit.y or absf(v.z) > limit.z:
		return "%s %s is out of range" % [what, v]
	return ""


## Why [param value] is not an int in [[param low], [param high]], or "".
static func check_int(value: Variant, low: int, high: int, what: String) -> String:
	if typeof(value) != TYPE_INT:
		return "%s is a %s, not an int" % [what, type_string(typeof(value))]
	var i: int = value
	if i < low or i > high:
		return "%s %d is out of [%d, %d]" % [what, i, low, high]
	return ""


## Why [param value] is not a finite float (an int is accepted) in [[param low],
## [param high]], or "".
static func check_float(value: Variant, low: float, high: float, what: String) -> String:
	if typeof(value) != TYPE_FLOAT and typeof(value) != TYPE_INT:
		return "%s is a %s, not a number" % [what, type_string(typeof(value))]
	var f: float = value
	if not is_finite(f) or f < low or f > high:
		return "%s %s is out of [%s, %s]" % [what, f, low, high]
	return ""


## Why [param value] is not a player name, or "".
static func check_name(value: Variant) -> String:
	if typeof(value) != TYPE_STRING:
		return "name is a %s, not a String" % type_string(typeof(value))
	var text: String = value
	if text.strip_edges().is_empty() or text.length() > MAX_NAME_LENGTH:
		return "name must have 1 to %d characters" % MAX_NAME_LENGTH
	return ""


## Why the server's lobby ([param rows] of [peer, name, seat, ready] for a court of
## [param seat_count] seats) is malformed, or "".
static func check_lobby(rows: Variant, seat_count: Variant) -> String:
	if typeof(rows) != TYPE_ARRAY:
		return "rows are a %s, not an Array" % type_string(typeof(rows))
	if typeof(seat_count) != TYPE_INT or not SEAT_COUNTS.has(seat_count):
		return "%s seats" % str(seat_count).left(16)
	var list: Array = rows
	for row: Variant in list:
		var r: Array = row if typeof(row) == TYPE_ARRAY else []
		if r.size() != 4 or typeof(r[0]) != TYPE_INT or typeof(r[2]) != TYPE_INT:
			return "a malformed row"
		if typeof(r[3]) != TYPE_BOOL or not check_name(r[1]).is_empty():
			return "a malformed row"
		if r[2] < 0 or r[2] >= seat_count:
			return "a row with seat %d" % r[2]
	return ""


## The box (half extents) received positions must lie in, for [param court].
static func position_limit(court: PongCourt) -> Vector3:
	var margin: Vector3 = Vector3.ONE * POSITION_MARGIN_M
	return Vector3(court.half_width, court.wall_height, court.half_length) + margin


## The checks of one ball state {epoch, seq, time, position, velocity, spin}: "" or why
## not. [param max_spin] in rad/s.
static func check_ball(
	epoch: Variant,
	seq: Variant,
	time_s: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant,
	court: PongCourt,
	max_spin: float
) -> String:
	var speed: float = court.max_ball_speed * SPEED_MARGIN
	var spin_limit: float = max_spin * SPEED_MARGIN
	for reason: String in [
		check_int(epoch, 0, 1 << 30, "epoch"),
		check_int(seq, 0, 1 << 40, "seq"),
		check_float(time_s, 0.0, 1e7, "time"),
		check_vector(position, position_limit(court), "position"),
		check_vector(velocity, Vector3.ONE * speed, "velocity"),
		check_vector(spin, Vector3.ONE * spin_limit, "spin"),
	]:
		if not reason.is_empty():
			return reason
	return ""


## The checks of one pose {seat, avatar, paddle offset, paddle velocity, normal}: "" or
## why not. [param reach]: the paddle's reach from its avatar, metres.
static func check_pose(
	seat: Variant,
	seats: int,
	avatar: Variant,
	offset: Variant,
	velocity: Variant,
	normal: Variant,
	court: PongCourt,
	reach: float
) -> String:
	var reach_limit: Vector3 = Vector3.ONE * (reach + POSITION_MARGIN_M)
	for reason: String in [
		check_int(seat, 0, seats - 1, "seat"),
		check_vector(avatar, position_limit(court), "avatar"),
		check_vector(offset, reach_limit, "paddle offset"),
		check_vector(velocity, Vector3.ONE * court.max_ball_speed * 4.0, "paddle velocity"),
		check_vector(normal, Vector3.ONE * 1.01, "normal"),
	]:
		if not reason.is_empty():
			return reason
	var n: Vector3 = normal
	if absf(n.length() - 1.0) > 0.01:
		return "normal is not a unit vector"
	return ""


## ENet's hard cap on an unacknowledged packet for a path of round trip [param rtt_ms]
## with [param variance_ms] mean deviation, as ENet measures them.
static func timeout_max_ms(rtt_ms: float, variance_ms: float) -> int:
	var rto_ms: float = maxf(rtt_ms, 0.0) + 4.0 * maxf(variance_ms, 0.0)
	return clampi(roundi(TIMEOUT_RTOS * rto_ms), TIMEOUT_MAX_MS, TIMEOUT_CEILING_MS)


## Silence after which a peer is taken for dead, seconds, on a path of round trip
## [param rtt_s] with mean deviation [param jitter_s] (ENet's measures): the beats a live
## peer may lose in a row, plus the round trip (a queue on the path can hold a beat that
## long) and four deviations, within [[constant HEARTBEAT_TIMEOUT_MIN_S],
## [constant HEARTBEAT_TIMEOUT_MAX_S]].
static func heartbeat_timeout_s(rtt_s: float, jitter_s: float) -> float:
	var patience: float = HEARTBEAT_MISSES / HEARTBEAT_HZ + maxf(rtt_s, 0.0)
	patience += 4.0 * maxf(jitter_s, 0.0)
	return clampf(patience, HEARTBEAT_TIMEOUT_MIN_S, HEARTBEAT_TIMEOUT_MAX_S)


## Whether [param point] lies in [param territory] of a court of [param seats], or within
## [param margin] metres of it along the floor.
static func near_territory(point: Vector3, territory: int, seats: int, margin: float) -> bool:
	if PongCourt.territory_of(point, seats) == territory:
		return true
	if margin <= 0.0:
		return false
	for step: int in 8:
		var angle: float = step * TAU / 8.0
		var offset: Vector3 = Vector3(cos(angle), 0.0, sin(angle)) * margin
		if PongCourt.territory_of(point + offset, seats) == territory:
			return true
	return false


## Why [param value] is not a unit [Vector3] (within 1 %), or "".
static func check_unit(value: Variant, what: String) -> String:
	var reason: String = check_vector(value, Vector3.ONE * 1.01, what)
	if not reason.is_empty():
		return reason
	var v: Vector3 = value
	return "%s is not a unit vector" % what if absf(v.length() - 1.0) > 0.01 else ""


## The checks of one shot {seat, id, origin, direction, time}: "" or why not.
static func check_bullet(
	seat: Variant,
	seats: int,
	id: Variant,
	origin: Variant,
	direction: Variant,
	time_s: Variant,
	court: PongCourt
) -> String:
	for reason: String in [
		check_int(seat, 0, seats - 1, "seat"),
		check_int(id, 0, MAX_WEAPON_ID, "bullet id"),
		check_vector(origin, position_limit(court), "origin"),
		check_unit(direction, "direction"),
		check_float(time_s, 0.0, 1e7, "time"),
	]:
		if not reason.is_empty():
			return reason
	return ""


## The checks of one mine {seat, id, position, kind}: "" or why not. A mine lies on the
## floor inside the walls, in another seat's territory, and its kind is the seat's
## [param id]-th ([constant PongMines.KINDS]).
static func check_mine(
	seat: Variant, seats: int, id: Variant, position: Variant, kind: Variant, court: PongCourt
) -> String:
	var floor_box: Vector3 = Vector3(court.half_width, FLOOR_TOLERANCE_M, court.half_length)
	for reason: String in [
		check_int(seat, 0, seats - 1, "seat"),
		check_int(id, 0, PongMines.KINDS.size() - 1, "mine id"),
		check_vector(position, floor_box, "mine position"),
	]:
		if not reason.is_empty():
			return reason
	var mine_id: int = id
	if typeof(kind) != TYPE_STRING or kind != PongMines.KINDS[mine_id]:
		return (
			"kind %s is not mine %d's, %s" % [str(kind).left(32), mine_id, PongMines.KINDS[mine_id]]
		)
	var owner: int = seat
	var at: Vector3 = position
	if PongCourt.territory_of(at, seats) == owner:
		return "mine in its owner's own territory"
	return ""


## The checks of one weapon hurt {victim, cause, weapon seat, weapon id}: "" or why not.
static func check_weapon_hurt(
	victim: Variant, seats: int, cause: Variant, seat: Variant, id: Variant
) -> String:
	for reason: String in [
		check_int(victim, 0, seats - 1, "victim"),
		check_int(seat, 0, seats - 1, "weapon seat"),
		check_int(id, 0, MAX_WEAPON_ID, "weapon id"),
	]:
		if not reason.is_empty():
			return reason
	if typeof(cause) != TYPE_STRING or not WEAPON_CAUSES.has(cause):
		return "cause %s is not a weapon" % str(cause).left(32)
	if victim == seat:
		return "a weapon never hurts its owner"
	return ""
