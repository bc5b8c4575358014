class_name HapticsServo
extends RefCounted
## The servo side of the [code]Haptics[/code] door ([code]Haptics.servo[/code]): the 1 kHz
## rendering thread's life, its statistics and its telemetry. Without the native extension
## it never runs and every answer is neutral.

## The servo started or stopped.
signal changed

## [method start] given this spin uses [member default_spin_us]; HapticsServer.start given
## it uses the servo's own (HapticsServer.DEFAULT_SPIN_US when the thread has real time,
## none without).
const SPIN_US_DEFAULT := -1.0

## The busy-wait before each deadline, in microseconds, that [method start] uses when given
## none. The [code]Haptics[/code] autoload sets it from the project setting
## [code]haptics/servo/spin_us[/code], so restarts (a device reopened, a Pong match ended)
## keep it.
var default_spin_us: float = SPIN_US_DEFAULT

var _server: Object = null
var _default_rate_hz: float = 0.0


func _init(server: Object, default_rate_hz: float) -> void:
	_server = server
	_default_rate_hz = default_rate_hz


## Starts the servo thread at [param rate_hz] (HapticsServer.MIN_RATE_HZ to MAX_RATE_HZ;
## 0: the default rate), busy-waiting [param spin_us] microseconds before each deadline (0 to
## half a period; [constant SPIN_US_DEFAULT]: [member default_spin_us]). A refused value is
## reported naming it, and the servo does not start.
func start(rate_hz: float = 0.0, spin_us: float = SPIN_US_DEFAULT) -> bool:
	if _server == null:
		return false
	var started: bool = _server.call(
		&"start",
		rate_hz if rate_hz > 0.0 else _default_rate_hz,
		default_spin_us if spin_us == SPIN_US_DEFAULT else spin_us
	)
	changed.emit()
	return started


## Stops the servo thread; the device is left at zero force.
func stop() -> void:
	if _server != null:
		_server.call(&"stop")
		changed.emit()


func is_running() -> bool:
	return _server != null and _server.call(&"is_running")


## "" while rendering is healthy, else why it stopped (e.g. the device was unplugged).
func get_status() -> String:
	return str(_server.call(&"get_servo_status")) if _server != null else ""


## Loop statistics (rate_hz, period_p99_ms, late_ticks, realtime…); empty without the
## extension.
func get_stats() -> Dictionary:
	return _server.call(&"get_stats") if _server != null else {}


## The achieved rate in Hz, 0 when the servo is not running.
func get_rate_hz() -> float:
	return float(get_stats().get("rate_hz", 0.0)) if is_running() else 0.0


## Up to [param max_samples] telemetry samples of [method get_telemetry_columns] floats
## each, oldest first, in device axes (y up); empty without the extension. Telemetry is off
## until a call turns it on (the [code]Haptics[/code] autoload turns it off at
## start: a game that never drains it is not counted drops).
func drain_telemetry(max_samples: int) -> PackedFloat32Array:
	if _server == null:
		return PackedFloat32Array()
	var config: Dictionary = _server.call(&"get_config")
	if not config["telemetry"]["enabled"]:
		_server.call(&"set_config", "telemetry", {"enabled": true})
	return _server.call(&"drain_telemetry", max_samples)


## The names of a telemetry sample's floats, in order.
func get_telemetry_columns() -> PackedStringArray:
	return PackedStringArray(_server.call(&"get_telemetry_columns") if _server != null else [])
