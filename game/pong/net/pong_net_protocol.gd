class_name PongNetProtocol
extends RefCounted
## The facts of networked Haptic Battle Pong that are not a message's: the version, the
## seats, ENet's timeouts and slots, the heartbeat, the budget of bad messages; and the checks
## of a received message against this match's court (its fields' own limits are the schema's,
## checked as it is decoded: [code]pong_net_messages.schema.toml[/code], [PongNetRouter]).
## A message that fails a check is dropped and counted against its sender
## ([method PongNetSession.misbehaved]); the game goes on.

## Sent and compared at connect (auth): peers of another protocol version are refused.
const VERSION: String = "hbp-net-4"
const DEFAULT_PORT: int = 7420
## Seats (territories) a match may have.
const MAX_SEATS: int = 4
## The courts a match can have: two players, or four on a square court.
const SEAT_COUNTS: Array[int] = [2, MAX_SEATS]
## Longest player name, characters (the lobby's field; the hello carries up to
## [constant PongNetFacts.NET_MAX_NAME_BYTES] bytes of it).
const MAX_NAME_LENGTH: int = 24
## Longest auth payload accepted, bytes (a version string).
const MAX_AUTH_BYTES: int = 64
## How far outside the court a received position may lie (a ball state extrapolated by the
## sender, a paddle at full reach), metres.
const POSITION_MARGIN_M: float = 1.0
## Received speeds may exceed the servo's caps by this factor (the sender's extrapolation).
const SPEED_MARGIN: float = 1.5
## A seat's shots are at least its cooldown apart in its servo's time; this share of it is
## accepted (the firer counts the cooldown in game time, which a real-time game's frames
## round).
const COOLDOWN_SHARE: float = 0.75
## How far off the floor a received mine may lie, metres.
const FLOOR_TOLERANCE_M: float = 0.01

## ENet drops a peer whose reliable packets stay unanswered past its timeout; the heartbeat,
## which knows who holds a seat, decides instead (a seat is kept through [constant
## SEAT_GRACE_S] of silence), so ENet's patience outlasts it: ENet tries a packet (its own
## ping) again with doubling waits, and one sent as a hiccup began may next be tried up to
## about twice the hiccup later. ENet's own timeouts, tuned to the round trip (at most 8 s),
## had dropped live peers after a lossy burst or a stalled frame and kicked players for a
## one-second Wi-Fi hiccup (docs/pong-networking.md).
const TIMEOUT_LIMIT: int = 32
const ENET_PATIENCE_MS: int = int(4.0 * SEAT_GRACE_S * 1000.0)
## A client connecting to nobody gives up after a few seconds (docs/networking.md, "ENet's
## timeouts and how a dead peer is noticed"); a 3 s cap, so that a lossy path does not fail
## the handshake.
const CONNECT_TIMEOUT_MIN_MS: int = 500
const CONNECT_TIMEOUT_MAX_MS: int = 3000
## A join that gets no answer tries again until this many seconds after it began, telling
## the player: a loss burst hid the server's first answers and a join gave up at 5 s.
const JOIN_PATIENCE_S: float = 15.0
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

## The heartbeat: every connected pair sends each other a [PongNetBeatMessage] this often, and
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
## Silence allowed a peer that said it stalls to load a match's court: its first frames
## compile the court's shaders, measured at 3.75 s on a loaded two-core machine without a
## shader cache; a player there must not lose the match before it starts.
const LOAD_STALL_TIMEOUT_S: float = 10.0
## A player silent in a match keeps the seat this long: from the heartbeat's limit on the
## computer stands in (the rally goes on), and when packets return the player takes the
## seat back. After it the seat is given up. ENet's patience is past it.
const SEAT_GRACE_S: float = 15.0
## A client whose server has been silent this long in a match connects again and rejoins
## ([PongNetRejoins]): its address may have changed (a laptop that roamed to another Wi-Fi, a
## NAT that rebound its port), and then the old connection never hears the server again. A
## hiccup shorter than this ends on the old connection; what is left of the grace is for the
## new connection's handshake through whatever made the path silent.
const REJOIN_AFTER_S: float = 8.0
## Seconds after a silent player is back during which what it sent while cut off (its shots,
## claims and hand-off requests, about a seat the computer played meanwhile) is refused but
## not counted against it: they arrive within a second of its return.
const RETURN_SETTLE_S: float = 2.0
## ENet peer slots of a server: ENet's most (its peer id has 12 bits). ENet keeps a peer for
## every CONNECT datagram it answers until the handshake completes or about 31.5 s pass, and
## Godot shows no such half-open peer to a script (ENetConnection.get_peers() lists a peer only
## once it has connected), so slots are what a flood of crafted CONNECTs uses up: six slots
## let 12 datagrams lock the players out for 30 s, 1024 a flood of 34 a second. 4095 hold
## one of 130 a second; above that a server nobody is connected to opens a new ENet host
## ([PongNetFlood]) and the kernel's guard keeps them (tools/net/flood-guard.sh,
## docs/pong-networking.md, "Floods"). An empty slot costs a few hundred bytes and next to
## nothing per frame.
const ENET_SLOTS: int = 4095
## Connections from one address that have connected at ENet's level but not passed the
## version check: more are not taken (the oldest is dropped), so one address cannot hold
## the lobby's attention. A household behind one NAT joins with up to a seat each.
const HALF_OPEN_PER_ADDRESS: int = MAX_SEATS

## Bad messages (malformed, or impossible such as a forged hurt) a peer may send: the first
## is logged, the rest are counted, and the server disconnects a peer that reaches this
## many within a while ([constant MISBEHAVIOUR_FORGIVEN_S]). An honest peer should send none
## (races of the authority are not counted).
const MISBEHAVIOUR_BUDGET: int = 16
## Seconds after which one of a peer's bad messages no longer counts toward
## [constant MISBEHAVIOUR_BUDGET] ([PongNetBudget]): a forger sends its 16 within a second, an
## honest peer's rare refusal is forgiven before the next.
const MISBEHAVIOUR_FORGIVEN_S: float = 30.0
## Stale but well-formed messages a peer may send in a second before they count as one bad
## message ([PongNetNoise]): a master streams at most [constant PongNetPlay.MAX_STREAM_HZ]
## states a second, and an honest hand-off request is one per transfer.
const STALE_STATES_PER_S: int = 250
const STALE_REQUESTS_PER_S: int = 20


## Why [param name] is not a player's name (1 to [constant MAX_NAME_LENGTH] characters, not
## all blank), or "".
static func check_name(name: String) -> String:
	if name.strip_edges().is_empty() or name.length() > MAX_NAME_LENGTH:
		return "a name must have 1 to %d characters" % MAX_NAME_LENGTH
	return ""


## The box (half extents) received positions must lie in, for [param court].
static func position_limit(court: PongCourt) -> Vector3:
	var margin: Vector3 = Vector3.ONE * POSITION_MARGIN_M
	return Vector3(court.half_width, court.wall_height, court.half_length) + margin


## Why [param value] is not within [param limit] of the origin along each axis, or "".
static func check_box(value: Vector3, limit: Vector3, what: String) -> String:
	if absf(value.x) > limit.x or absf(value.y) > limit.y or absf(value.z) > limit.z:
		return "%s %s is out of range" % [what, value]
	return ""


## Why a ball ([param position], [param velocity], [param spin]) cannot be in this match's
## [param court] (its box, its speed cap, the spin cap [param max_spin] in rad/s, each with
## the sender's extrapolation's margin), or "".
static func check_ball(
	position: Vector3, velocity: Vector3, spin: Vector3, court: PongCourt, max_spin: float
) -> String:
	for reason: String in [
		check_box(position, position_limit(court), "position"),
		check_box(velocity, Vector3.ONE * court.max_ball_speed * SPEED_MARGIN, "velocity"),
		check_box(spin, Vector3.ONE * max_spin * SPEED_MARGIN, "spin"),
	]:
		if not reason.is_empty():
			return reason
	return ""


## Why a seat number [param seat] is not one of a match of [param seats], or "".
static func check_seat(seat: int, seats: int, what: String = "seat") -> String:
	return "" if seat < seats else "%s %d of a court of %d" % [what, seat, seats]


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
## Whether [param identity] may be presented in a hello: 1 to
## [constant PongNetFacts.NET_MAX_IDENTITY_BYTES] hex digits.
static func is_identity(identity: String) -> bool:
	if (
		identity.length() > PongNetFacts.NET_MAX_IDENTITY_BYTES
		or not identity.is_valid_hex_number()
	):
		return false
	return identity[0] != "+" and identity[0] != "-"  # Godot's hex numbers may be signed.


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
