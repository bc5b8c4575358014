extends Node
## `make soak` (not part of `make test`): level 1 under the autopilot, started again at each
## goal, for [code]--seconds=N[/code] (default 600) with the servo at 1 kHz on the simulated
## device, telemetry drained every physics frame as a recorder would. Prints one line a minute
## and then the figures, each against its bound, and exits 1 if any is missed:
## [br]- rate: every minute's and the whole run's within 0.05 % of nominal (no drift);
## [br]- telemetry drops: none;
## [br]- resident memory: grows less than 1 MB from the end of the warm-up to the end;
## [br]- lateness: no tick woke a whole period or more after its deadline, none skipped.
##
## tools/godot --headless --path . res://tests/soak/soak.tscn -- [--seconds=N] [--warmup=N]

const GAME_SCENE: PackedScene = preload("res://game/main/game.tscn")
const RATE_TOLERANCE_PERCENT: float = 0.05
const MEMORY_GROWTH_LIMIT_BYTES: int = 1_000_000
const TELEMETRY_BATCH: int = 4096

var _seconds: float = 600.0
var _warmup_seconds: float = 60.0
var _game: Game = null
var _levels_started: int = 0
var _goals: int = 0
var _floats_drained: int = 0


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--seconds="):
			_seconds = maxf(10.0, arg.get_slice("=", 1).to_float())
		elif arg.begins_with("--warmup="):
			_warmup_seconds = maxf(1.0, arg.get_slice("=", 1).to_float())
	_warmup_seconds = minf(_warmup_seconds, _seconds * 0.5)
	Haptics.hand_follows_input = false
	_start_level()
	var exit_code: int = await _soak()
	CleanExit.quit(exit_code)


func _physics_process(_delta: float) -> void:
	_floats_drained += Haptics.servo.drain_telemetry(TELEMETRY_BATCH).size()


func _start_level() -> void:
	if _game != null:
		remove_child(_game)
		_game.queue_free()
	_game = GAME_SCENE.instantiate() as Game
	var pilot: LevelPilot = LevelPilot.new()
	pilot.seconds = 0.0
	pilot.print_status = false
	pilot.finished.connect(_on_autopilot_finished)
	_game.pilot = pilot
	add_child(_game)
	_levels_started += 1


func _on_autopilot_finished(reason: String) -> void:
	if reason == "goal":
		_goals += 1
	_start_level.call_deferred()


func _soak() -> int:
	var stride: int = Haptics.servo.get_telemetry_columns().size()
	var start_us: int = Time.get_ticks_usec()
	var first: HapticServoStats = Haptics.servo.get_stats()
	var minute_rates: PackedFloat64Array = []
	var last_minute: HapticServoStats = first
	var last_minute_us: int = start_us
	var rss_after_warmup: int = -1
	var rss_max: int = 0
	print(
		(
			"soak: %.0f s (warm-up %.0f s), servo %s at %.0f Hz, telemetry stride %d floats"
			% [
				_seconds,
				_warmup_seconds,
				HapticRealtime.SCHEDULER_KIND_NAMES[first.scheduler],
				first.nominal_rate_hz,
				stride
			]
		)
	)
	while true:
		await get_tree().create_timer(1.0).timeout
		var now_us: int = Time.get_ticks_usec()
		var elapsed_s: float = (now_us - start_us) / 1e6
		var rss: int = _resident_bytes()
		if elapsed_s >= _warmup_seconds:
			if rss_after_warmup < 0:
				rss_after_warmup = rss
			rss_max = maxi(rss_max, rss)
		if now_us - last_minute_us >= 60_000_000 or elapsed_s >= _seconds:
			var stats: HapticServoStats = Haptics.servo.get_stats()
			var rate: float = (
				float(stats.ticks - last_minute.ticks) / ((now_us - last_minute_us) / 1e6)
			)
			minute_rates.append(rate)
			print(
				(
					"  t=%4.0f s  rate %.3f Hz  late %d  missed %d  latency max %.0f us  drops %d  RSS %.1f MB"
					% [
						elapsed_s,
						rate,
						stats.late_ticks,
						stats.missed_deadlines,
						stats.latency_max_s * 1e6,
						stats.telemetry_drops,
						rss / 1e6,
					]
				)
			)
			last_minute = stats
			last_minute_us = now_us
		if elapsed_s >= _seconds:
			break
	return _report(first, Haptics.servo.get_stats(), minute_rates, rss_after_warmup, rss_max)


func _report(
	first: HapticServoStats,
	last: HapticServoStats,
	minute_rates: PackedFloat64Array,
	rss_warm: int,
	rss_max: int
) -> int:
	var nominal: float = last.nominal_rate_hz
	var period_us: float = 1e6 / nominal
	var worst_minute: float = 0.0
	for rate: float in minute_rates:
		worst_minute = maxf(worst_minute, absf(rate - nominal) / nominal * 100.0)
	var whole_error: float = absf(last.achieved_rate_hz - nominal) / nominal * 100.0
	var drops: int = last.telemetry_drops - first.telemetry_drops
	var latency_max_us: float = last.latency_max_s * 1e6
	var stride: int = Haptics.servo.get_telemetry_columns().size()
	var rss_end: int = _resident_bytes()
	var growth: int = rss_end - rss_warm
	var checks: Array[Array] = [
		[
			"rate, whole run",
			"%.3f Hz, error %.4f %%" % [last.achieved_rate_hz, whole_error],
			whole_error <= RATE_TOLERANCE_PERCENT,
		],
		[
			"rate, worst minute",
			"error %.4f %% over %d minute(s)" % [worst_minute, minute_rates.size()],
			worst_minute <= RATE_TOLERANCE_PERCENT,
		],
		[
			"telemetry drops",
			"%d (%d samples drained)" % [drops, roundi(float(_floats_drained) / maxf(1.0, stride))],
			drops == 0,
		],
		[
			"resident memory growth after warm-up",
			(
				"%+.3f MB (%.1f MB at %.0f s, %.1f MB at the end, peak %.1f MB)"
				% [growth / 1e6, rss_warm / 1e6, _warmup_seconds, rss_end / 1e6, rss_max / 1e6]
			),
			growth < MEMORY_GROWTH_LIMIT_BYTES,
		],
		[
			"latest wake-up after a deadline",
			(
				"%.0f us (p99 %.0f us; a period is %.0f us), %d tick(s) > half a period"
				% [latency_max_us, last.latency_p99_s * 1e6, period_us, last.late_ticks]
			),
			latency_max_us < period_us,
		],
		[
			"deadlines skipped",
			"%d" % last.missed_deadlines,
			last.missed_deadlines == 0,
		],
	]
	print(
		(
			"soak figures: %d ticks, %d level run(s), %d goal(s); servo %s prio %d, %s"
			% [
				last.ticks,
				_levels_started,
				_goals,
				HapticRealtime.SCHEDULER_KIND_NAMES[last.scheduler],
				last.realtime_priority,
				Hud.servo_running_text(last.achieved_rate_hz, last),
			]
		)
	)
	var failed: int = 0
	for check: Array in checks:
		var met: bool = check[2]
		failed += 0 if met else 1
		print("  %-40s %-70s %s" % [check[0], check[1], "ok" if met else "MISSED"])
	print("soak: %s" % ("all bounds met" if failed == 0 else "%d bound(s) missed" % failed))
	return 0 if failed == 0 else 1


## Resident memory of this process (/proc/self/statm's second field, in pages of 4 KiB), or
## 0 where there is no /proc.
static func _resident_bytes() -> int:
	var statm: FileAccess = FileAccess.open("/proc/self/statm", FileAccess.READ)
	if statm == null:
		return 0
	# A /proc file has no size: read its line rather than its length.
	var fields: PackedStringArray = statm.get_line().split(" ")
	return fields[1].to_int() * 4096 if fields.size() > 1 else 0
