class_name PongNetCli
extends Node
## Networked Pong from the command line (after [code]--[/code]):
## [br][code]--server [--port=P] [--pong-net-seats=2|4][/code]: a dedicated server; shows
## nothing, starts a match when two players or more are ready, and again for each rematch;
## empty seats are computer players. The "Linux Server" export always is one.
## [br][code]--pong-net=host|join --port=P --address=A --name=N [--pong-net-seats=2|4][/code]:
## a player without the menu, ready as soon as it is in the lobby; the host starts the match
## when every player is ready; the game quits when the match is over.
## [br][code]--identity=HEX[/code]: the secret a player presents when it joins (by default one
## drawn at start): a game restarted with the same one takes back the seat kept for it in a
## running match.
## [br][code]--pong-net-max-seconds=S[/code]: quit (exit 0) after S seconds whatever happens:
## a server run for a while (a smoke test of an export, a supervised restart).
## [br]Exit codes: 0 done, 2 connection failed or refused, 3 no Pong renderer.
## [br]The seam for a scripted peer (the network tests' driver, [code]tests/net/[/code]): it
## adds this node to a scene of its own, configures the peer when [signal launched] hands it
## over (before it connects), may [method finish] the run, and learns of the end from
## [signal finishing].

## The peer is made (at /root/PongNet) and about to host or join: the moment to configure it.
signal launched(net: PongNet)
## The run ends with exit code [param code] because of [param why] ("failed", "server lost",
## "over", or a scripted peer's reason): the peer is still as the run left it.
signal finishing(code: int, why: String)

## Headless peers sleep this long per frame during a match (docs/networking.md, "Frame
## pacing of headless peers"): a message waits at most this long to be read, and the servo
## is stepped in 10 ms chunks whatever the frame rate. 1 ms frames took a peer 24-30 % of a
## core, 4 ms frames 15-19 %, for nothing a player sees.
const MATCH_SLEEP_USEC: int = 4000
## And this long between matches: a lobby message may wait 10 ms, and a server waiting for
## players runs 100 frames a second instead of 250.
const LOBBY_SLEEP_USEC: int = 10000
## The custom feature of the dedicated server's export preset.
const SERVER_FEATURE: String = "pong_server"

var net: PongNet = null
var options: Dictionary[String, String] = {}
## A server starts a match once this many players are in (and every one is ready).
var players_wanted: int = 2
## Whether a dedicated server plays match after match (false: the run ends with the first).
var serve_forever: bool = true

var _finishing: bool = false
var _readied: bool = false


## Whether [param args] ask for networked Pong (the "Linux Server" export always does).
static func wants(args: PackedStringArray) -> bool:
	if OS.has_feature(SERVER_FEATURE):
		return true
	for arg: String in args:
		if arg == "--server" or arg.begins_with("--pong-net="):
			return true
	return false


static func parse(args: PackedStringArray) -> Dictionary[String, String]:
	var parsed: Dictionary[String, String] = {}
	for arg: String in args:
		if not arg.begins_with("--"):
			continue
		var body: String = arg.substr(2)
		var at: int = body.find("=")
		if at < 0:
			parsed[body] = "true"
		else:
			parsed[body.substr(0, at)] = body.substr(at + 1)
	return parsed


func _ready() -> void:
	# The root is still adding the main scene: PongNet goes next to it a moment later.
	_launch.call_deferred()


## Ends the run: [signal finishing], then the peer leaves and the game quits with [param code].
func finish(code: int, why: String) -> void:
	if _finishing:
		return
	_finishing = true
	finishing.emit(code, why)
	print("PongNet: done (%s)" % why)
	if net != null:
		net.leave()
	CleanExit.quit(code)


## The option [param key] of the command line, or [param default].
func option(key: String, default: String) -> String:
	return options[key] if options.has(key) else default


func _launch() -> void:
	options = parse(OS.get_cmdline_user_args())
	var server: bool = options.has("server") or OS.has_feature(SERVER_FEATURE)
	var role: String = "server" if server else option("pong-net", "host")
	var port: int = option("port", str(PongNetProtocol.DEFAULT_PORT)).to_int()
	var max_seconds: float = option("pong-net-max-seconds", "0").to_float()
	if max_seconds > 0.0:
		get_tree().create_timer(max_seconds, true, false, true).timeout.connect(
			finish.bind(0, "deadline")
		)
	_pace(false)
	net = PongNet.new()
	net.name = PongNet.NODE_NAME
	get_tree().root.add_child(net)
	net.my_name = option("name", role)
	net.dedicated = role == "server"
	net.autopilot = net.dedicated
	net.stepped = DisplayServer.get_name() == "headless"
	net.draws_screen = not net.stepped
	net.seats = option("pong-net-seats", "2").to_int()
	net.rejoins.identity = option("identity", net.rejoins.identity)
	launched.emit(net)
	if not PongNetProtocol.SEAT_COUNTS.has(net.seats):
		finish(2, "--pong-net-seats must be one of %s" % str(PongNetProtocol.SEAT_COUNTS))
		return
	if not PongNetProtocol.is_identity(net.rejoins.identity):
		finish(2, "--identity must be 1 to %d hex digits" % PongNetFacts.NET_MAX_IDENTITY_BYTES)
		return
	if net.stepped:
		# A stepped peer runs the servo by hand during a match; between matches nothing here
		# needs the autoload's 1 kHz thread.
		Haptics.servo.stop()
	net.status_changed.connect(func(text: String) -> void: print("PongNet: %s" % text))
	net.session.failed.connect(
		func(_reason: String) -> void:
			if not net.reconnect.is_reconnecting():  # A rejoin tries again.
				finish(2, "failed")
	)
	net.session.server_lost.connect(finish.bind(0, "server lost"))
	net.lobby_changed.connect(_on_lobby_changed)
	net.match_started.connect(_on_match_started)
	net.match_ended.connect(_on_match_ended)
	var error: String = ""
	if role == "join":
		error = net.join(option("address", "127.0.0.1"), port)
	else:
		error = net.host(port)
	if not error.is_empty():
		finish(2, error)


func _process(_delta: float) -> void:
	if net == null or _finishing or not net.session.is_server:
		return
	if net.can_start() and net.players.size() >= players_wanted:
		net.start_match()


# A player without the menu has no Ready button: it is ready once it is in the lobby.
func _on_lobby_changed() -> void:
	if not net.dedicated and not _readied and net.players.has(net.my_id()):
		_readied = true
		net.set_ready(true)


func _on_match_started() -> void:
	_pace(true)
	_readied = false


func _on_match_ended(_winner: int, why: String) -> void:
	_pace(false)
	if net.dedicated and why == "over" and serve_forever:
		net.close_screen()
		return
	if why == "over":
		finish(0, why)


# Headless, nothing waits for a display: the frame rate is the sleep between frames.
func _pace(in_match: bool) -> void:
	if DisplayServer.get_name() == "headless":
		OS.low_processor_usage_mode_sleep_usec = MATCH_SLEEP_USEC if in_match else LOBBY_SLEEP_USEC
