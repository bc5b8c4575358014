class_name PongNetCli
extends Node
## Networked Pong from the command line (after [code]--[/code]):
## [br][code]--server [--port=P][/code]: a dedicated server; shows nothing, starts a match
## when two players or more are ready, and again for each rematch.
## [br][code]--pong-net-seats=2|4[/code] (a server or host): the court's seats (default: 4
## when [code]--pong-net-peers[/code] is more than 2); empty seats are computer players.
## [br][code]--pong-net=host|join|local --port=P --address=A --name=N[/code]: a player
## without the menu; [code]local[/code] plays the same script without a network (the
## reference of the contact test).
## [br]Autopilot (headless test peers): [code]--pong-net-autopilot[/code] (the computer
## drives this peer's paddle, everyone readies up, the host starts when
## [code]--pong-net-peers=N[/code] players are in), [code]--pong-net-seconds=S[/code] (play
## that long, then write the report and quit), [code]--pong-net-max-seconds=S[/code] (quit
## after S wall seconds whatever happens), [code]--pong-net-report=FILE[/code] (JSON),
## [code]--pong-net-script=rally|hit|remote[/code] (hit: this peer's seat is a still device
## paddle and the first serve goes to seat 1, so the report holds the contact's force
## profile; remote: [PongNetRemoteMineScript], seat 1 steps on seat 0's remote mine and
## reports the coupling's work on its hand, [code]--pong-net-passivity=off[/code] without
## the passivity rule), [code]--pong-net-health=N[/code], [code]--pong-net-version=V[/code] (claim
## another protocol version: refused), [code]--pong-net-weapon-rate=X[/code] (the
## computer players fire and place mines X times as often: the weapons test),
## [code]--pong-net-realtime[/code] (headless
## too, run the servo thread at 1 kHz as a windowed game does, instead of stepping it).
## Exit codes: 0 done, 2 connection failed or refused, 3 no Pong renderer.

## Headless peers sleep this long per frame during a match (docs/networking.md, "Frame
## pacing of headless peers": the default 6900 us makes every message wait up to a frame,
## and a stepped peer steps its servo once a frame).
const MATCH_SLEEP_USEC: int = 1000
## And this long between matches: a lobby message may wait 10 ms, and a server waiting for
## players runs 100 frames a second instead of 1000.
const LOBBY_SLEEP_USEC: int = 10000
## The custom feature of the dedicated server's export preset.
const SERVER_FEATURE: String = "pong_server"

var net: PongNet = null
var options: Dictionary[String, String] = {}
var report_path: String = ""
var seconds: float = 0.0
var script_name: String = "rally"
var peers_wanted: int = 2
var max_seconds: float = 0.0

var _match_clock: float = -1.0
var _seat: int = -1
var _readied: bool = false
var _profile: PongNetContactProfile = null
var _remote: PongNetRemoteMineScript = null
var _finishing: bool = false


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


func _launch() -> void:
	options = parse(OS.get_cmdline_user_args())
	var server: bool = options.has("server") or OS.has_feature(SERVER_FEATURE)
	var role: String = "server" if server else _option("pong-net", "host")
	var port: int = _option("port", str(PongNetProtocol.DEFAULT_PORT)).to_int()
	report_path = _option("pong-net-report", "")
	seconds = _option("pong-net-seconds", "0").to_float()
	script_name = _option("pong-net-script", "rally")
	peers_wanted = _option("pong-net-peers", "2").to_int()
	max_seconds = _option("pong-net-max-seconds", "0").to_float()
	if max_seconds > 0.0:
		get_tree().create_timer(max_seconds, true, false, true).timeout.connect(
			_finish.bind(0, "deadline")
		)
	_pace(false)
	if role == "local":
		_profile = PongNetContactProfile.new()
		add_child(_profile)
		_profile.done.connect(_finish.bind(0, "local"))
		_profile.play_local(_option("pong-net-health", "5").to_int())
		return
	net = PongNet.new()
	net.name = PongNet.NODE_NAME
	get_tree().root.add_child(net)
	net.my_name = _option("name", role)
	net.dedicated = role == "server"
	net.autopilot = options.has("pong-net-autopilot") or net.dedicated
	net.stepped = DisplayServer.get_name() == "headless" and not options.has("pong-net-realtime")
	if net.stepped:
		# A stepped peer runs the servo by hand during a match; between matches nothing here
		# needs the autoload's 1 kHz thread.
		Haptics.servo.stop()
	net.start_health = _option("pong-net-health", str(PongRules.DEFAULT_START_HEALTH)).to_int()
	var seats_default: int = PongNetProtocol.MAX_SEATS if peers_wanted > 2 else 2
	net.seats = _option("pong-net-seats", str(seats_default)).to_int()
	if not PongNetProtocol.SEAT_COUNTS.has(net.seats):
		_finish(2, "--pong-net-seats must be one of %s" % str(PongNetProtocol.SEAT_COUNTS))
		return
	net.session.version = _option("pong-net-version", PongNetProtocol.VERSION)
	net.status_changed.connect(func(text: String) -> void: print("PongNet: %s" % text))
	net.session.failed.connect(func(_reason: String) -> void: _finish(2, "failed"))
	net.session.server_lost.connect(_finish.bind(0, "server lost"))
	net.lobby_changed.connect(_on_lobby_changed)
	net.match_started.connect(_on_match_started)
	net.match_ended.connect(_on_match_ended)
	if script_name == "hit":
		_profile = PongNetContactProfile.new()
		add_child(_profile)
		net.local_controller_factory = _profile.make_still_paddle
	elif script_name == "remote":
		_remote = PongNetRemoteMineScript.new()
		_remote.passivity = _option("pong-net-passivity", "on") != "off"
		add_child(_remote)
		net.local_controller_factory = _remote.make_controller
	var error: String = ""
	if role == "join":
		error = net.join(_option("address", "127.0.0.1"), port)
	else:
		error = net.host(port)
	if not error.is_empty():
		_finish(2, error)


func _option(key: String, default: String) -> String:
	return options[key] if options.has(key) else default


func _process(delta: float) -> void:
	if net == null or _finishing:
		return
	if net.session.is_server and net.can_start() and net.players.size() >= peers_wanted:
		net.start_match()
	if _match_clock < 0.0:
		return
	_match_clock += delta
	if seconds > 0.0 and _match_clock >= seconds:
		_finish(0, "time")


func _on_lobby_changed() -> void:
	if net.autopilot and not _readied and net.players.has(net.my_id()):
		_readied = true
		net.set_ready(true)
	elif net.dedicated:
		pass


func _on_match_started() -> void:
	_pace(true)
	_match_clock = 0.0
	_readied = false
	_seat = net.my_seat()
	var rate: float = _option("pong-net-weapon-rate", "1").to_float()
	for controller: PongController in net.play.match_node.controllers:
		if controller is PongAi and rate > 0.0:
			(controller as PongAi).mine_rate_per_s *= rate
			(controller as PongAi).fire_interval_s /= rate
	if _remote != null:
		_remote.follow(net.play)
	if script_name == "hit":
		_profile.follow(net.play)
		if net.session.is_server:
			net.play.match_node.referee.receiver = PongNetContactProfile.SEAT
			var court: PongCourt = net.play.match_node.court
			net.play.serve_aim = func(receiver: int, avatar: Vector3) -> Vector3:
				if receiver != PongNetContactProfile.SEAT:
					return avatar
				return PongNetContactProfile.aim_for(court, avatar)


func _on_match_ended(_winner: int, why: String) -> void:
	_pace(false)
	if net.dedicated and why == "over" and seconds <= 0.0:
		net.close_screen()
		return
	if why == "over":
		_finish(0, why)


func _finish(code: int, why: String) -> void:
	if _finishing:
		return
	_finishing = true
	var data: Dictionary = {"exit": why}
	if net != null:
		var play: PongNetPlay = net.play
		data.merge(play.report.to_dict(play.ball.smoother, play.authority))
		data["seat"] = _seat
		data["error"] = net.session.last_error
		data["health"] = _health()
		# The rules the health came from, so a reader can recount it from the hurts.
		data["start_health"] = net.start_health
		data["damage"] = PongRules.DAMAGE
		data["controllers"] = _controllers()
	if _profile != null:
		data["contact"] = _profile.to_dict()
	if _remote != null:
		data["remote_mine"] = _remote.to_dict()
	if not report_path.is_empty():
		var file: FileAccess = FileAccess.open(report_path, FileAccess.WRITE)
		if file != null:
			file.store_string(JSON.stringify(data))
			file.close()
	print("PongNet: done (%s)" % why)
	if net != null:
		net.leave()
	CleanExit.quit(code)


func _health() -> Array[int]:
	var health: Array[int] = []
	var match_node: PongMatch = net.play.match_node
	if match_node != null and match_node.rules != null:
		for seat: int in net.seats:
			health.append(match_node.rules.get_health(seat))
	return health


## Who drove each seat here at the end: computer, remote (the network) or local.
func _controllers() -> Array[String]:
	var kinds: Array[String] = []
	var match_node: PongMatch = net.play.match_node
	if match_node == null:
		return kinds
	for controller: PongController in match_node.controllers:
		if controller is PongAi:
			kinds.append("computer")
		elif controller is PongNetRemotePlayer:
			kinds.append("remote")
		else:
			kinds.append("local")
	return kinds


# Headless, nothing waits for a display: the frame rate is the sleep between frames.
func _pace(in_match: bool) -> void:
	if DisplayServer.get_name() == "headless":
		OS.low_processor_usage_mode_sleep_usec = MATCH_SLEEP_USEC if in_match else LOBBY_SLEEP_USEC
