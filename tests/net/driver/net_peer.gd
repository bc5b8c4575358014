extends Node
## A networked-Pong peer for the process tests and the benchmark (tests/net/net_harness.py
## runs this scene by path): the game's own command line ([PongNetCli], the same options) with
## the test's options on top, wired in through the command line's seam ([signal
## PongNetCli.launched], [method PongNetCli.finish], [signal PongNetCli.finishing]):
## [br][code]--pong-net-autopilot[/code]: the computer drives this peer's paddle;
## [code]--pong-net-peers=N[/code]: a host starts once N players are in (default 2; more than
## 2 and no [code]--pong-net-seats[/code]: the four-seat court);
## [code]--pong-net-seconds=S[/code]: play that long, then write the report and quit (a
## dedicated server too, instead of serving the next match);
## [code]--pong-net-report=FILE[/code]: the JSON report ([code]net_report.gd[/code]);
## [code]--pong-net-script=rally|hit|remote[/code] (hit: this peer's seat is a still device
## paddle and the first serve goes to seat 1, so the report holds the contact's force
## profile; remote: [code]remote_mine_script.gd[/code], seat 1 steps on seat 0's remote mine
## and reports the coupling's work on its hand, [code]--pong-net-passivity=off[/code] without
## the passivity rule); [code]--pong-net=local[/code]: the hit without a network (the
## contact test's reference); [code]--pong-net-health=N[/code];
## [code]--pong-net-version=V[/code] (claim another protocol version: refused);
## [code]--pong-net-weapon-rate=X[/code] (the computer players fire and place mines X times
## as often); [code]--pong-net-realtime[/code] (headless too, run the servo thread at 1 kHz
## as a windowed game does, instead of stepping it); [code]--pong-net-load-stall=S[/code]
## (the frame that loads the match's court takes S seconds more, as a slow machine compiling
## its shaders for the first time does).
## A test tool, out of every export: under tests/ and in a folder Godot does not scan
## (.gdignore), as the rogue peer.

const NetReport := preload("res://tests/net/driver/net_report.gd")
const ContactProfile := preload("res://tests/net/driver/contact_profile.gd")
const RemoteMineScript := preload("res://tests/net/driver/remote_mine_script.gd")

## The game's command line, which this peer drives.
var cli: PongNetCli = null
var options: Dictionary[String, String] = {}
var report: NetReport = NetReport.new()
var report_path: String = ""
var seconds: float = 0.0
var script_name: String = "rally"

var _match_clock: float = -1.0
var _seat: int = -1
var _profile: ContactProfile = null
var _remote: RemoteMineScript = null


func _init() -> void:
	# After the game's nodes (PongNet steps the match): the ball is sampled as the frame
	# left it.
	process_priority = 100


func _ready() -> void:
	options = PongNetCli.parse(OS.get_cmdline_user_args())
	report_path = option("pong-net-report", "")
	seconds = option("pong-net-seconds", "0").to_float()
	script_name = option("pong-net-script", "rally")
	if option("pong-net", "") == "local":
		_play_local.call_deferred()
		return
	cli = PongNetCli.new()
	cli.launched.connect(_on_launched)
	cli.finishing.connect(_on_finishing)
	add_child(cli)


## The option [param key] of the command line, or [param default].
func option(key: String, default: String) -> String:
	return options[key] if options.has(key) else default


func _process(delta: float) -> void:
	if _match_clock < 0.0 or cli == null:
		return
	var play: PongNetPlay = cli.net.play
	if play.is_running():
		report.sample(play.match_node.snapshot, play.authority.is_master())
	_match_clock += delta
	if seconds > 0.0 and _match_clock >= seconds:
		cli.finish(0, "time")


# The peer exists and has not connected yet: the test's options.
func _on_launched(net: PongNet) -> void:
	var peers: int = option("pong-net-peers", "2").to_int()
	cli.players_wanted = peers
	if not options.has("pong-net-seats") and peers > 2:
		net.seats = PongNetProtocol.MAX_SEATS
	net.autopilot = net.autopilot or options.has("pong-net-autopilot")
	if options.has("pong-net-realtime"):
		net.stepped = false
	var health: String = option("pong-net-health", str(PongRules.DEFAULT_START_HEALTH))
	net.start_health = health.to_int()
	net.session.version = option("pong-net-version", PongNetProtocol.VERSION)
	cli.serve_forever = seconds <= 0.0
	report.watch(net.play)
	net.match_started.connect(_on_match_started)
	if script_name == "hit":
		_profile = ContactProfile.new()
		add_child(_profile)
		net.local_controller_factory = _profile.make_still_paddle
	elif script_name == "remote":
		_remote = RemoteMineScript.new()
		_remote.passivity = option("pong-net-passivity", "on") != "off"
		add_child(_remote)
		net.local_controller_factory = _remote.make_controller


func _on_match_started() -> void:
	var net: PongNet = cli.net
	var stall_s: float = option("pong-net-load-stall", "0").to_float()
	if stall_s > 0.0:
		var stalled: Dictionary = {"from_wall_s": NetReport.now()}
		OS.delay_msec(roundi(stall_s * 1000.0))
		stalled["to_wall_s"] = NetReport.now()
		report.extra["load_stall"] = stalled
	var rejoined: bool = _match_clock >= 0.0  # The client rejoined its match by itself.
	if not rejoined:
		_match_clock = 0.0
	_seat = net.my_seat()
	report.begin(net.play, rejoined)
	if rejoined:
		var entries: Array = report.extra.get_or_add("rejoined", [])
		entries.append({"wall_s": NetReport.now(), "peer": report.peer, "health": _health(net)})
	else:
		report.extra["health_at_start"] = _health(net)
	var rate: float = option("pong-net-weapon-rate", "1").to_float()
	for controller: PongController in net.play.match_node.controllers:
		if controller is PongAi and rate > 0.0:
			(controller as PongAi).mine_rate_per_s *= rate
			(controller as PongAi).fire_interval_s /= rate
	if _remote != null:
		_remote.follow(net.play)
	if script_name == "hit":
		_profile.follow(net.play)
		if net.session.is_server:
			net.play.match_node.referee.receiver = ContactProfile.SEAT
			var court: PongCourt = net.play.match_node.court
			net.play.serve_aim = func(receiver: int, avatar: Vector3) -> Vector3:
				if receiver != ContactProfile.SEAT:
					return avatar
				return ContactProfile.aim_for(court, avatar)


# The run ends (the command line's reason): the report, as the run left the peer.
func _on_finishing(_code: int, why: String) -> void:
	var net: PongNet = cli.net
	var data: Dictionary = {"exit": why}
	if net != null:
		if why == "server lost" and _match_clock >= 0.0:
			var lost: Dictionary = {"wall_s": NetReport.now(), "why": net.session.lost_reason}
			report.extra["server_lost"] = lost
		data.merge(report.to_dict())
		data["seat"] = _seat
		data["error"] = net.session.last_error
		data["health"] = _health(net)
		# The rules the health came from, so a reader can recount it from the hurts.
		data["start_health"] = net.start_health
		data["damage"] = PongRules.DAMAGE
		data["controllers"] = _controllers(net)
	if _profile != null:
		data["contact"] = _profile.to_dict()
	if _remote != null:
		data["remote_mine"] = _remote.to_dict()
	_write(data)


# The scripted hit without a network.
func _play_local() -> void:
	_profile = ContactProfile.new()
	add_child(_profile)
	_profile.play_local(option("pong-net-health", "5").to_int())
	_write({"exit": "local", "contact": _profile.to_dict()})
	print("PongNet: done (local)")
	CleanExit.quit(0)


func _write(data: Dictionary) -> void:
	if report_path.is_empty():
		return
	var file: FileAccess = FileAccess.open(report_path, FileAccess.WRITE)
	if file != null:
		file.store_string(JSON.stringify(data))
		file.close()


func _health(net: PongNet) -> Array[int]:
	var health: Array[int] = []
	var match_node: PongMatch = net.play.match_node
	if match_node != null and match_node.rules != null:
		for seat: int in net.seats:
			health.append(match_node.rules.get_health(seat))
	return health


## Who drove each seat here at the end: computer, remote (the network) or local.
func _controllers(net: PongNet) -> Array[String]:
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
