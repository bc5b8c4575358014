class_name HapticsServo
extends RefCounted
## The servo side of the [code]Haptics[/code] door ([code]Haptics.servo[/code]): the 1 kHz
## rendering thread's life, manual ticks, its statistics and its telemetry. Without the
## native extension it never runs and every answer is neutral.

## The servo started or stopped, or its settings were applied.
signal changed

## [method start] given this spin uses [member default_spin_us]; the library given it uses
## the servo's own ([constant HapticServoConstants.DEFAULT_SPIN_NS] when the thread has real
## time and holds the latency, [constant HapticServoConstants.UNHELD_SPIN_NS] with real time
## alone, none without).
const SPIN_US_DEFAULT := -1.0
const HapticsBackend := preload("res://addons/haptics/door/haptics_backend.gd")

## The busy-wait before each deadline, in microseconds, that [method start] uses when given
## none. The [code]Haptics[/code] autoload sets it from the project setting
## [code]haptics/servo/spin_us[/code], so restarts (a device reopened, a Pong match ended)
## keep it.
var default_spin_us: float = SPIN_US_DEFAULT

var _backend: HapticsBackend = null


func _init(backend: HapticsBackend) -> void:
	_backend = backend


## Starts the servo thread at [param rate_hz]
## ([constant HapticServoConstants.MIN_RATE_HZ] to [constant HapticServoConstants.MAX_RATE_HZ];
## 0: the default rate), busy-waiting [param spin_us] microseconds before each deadline (0 to
## half a period; [constant SPIN_US_DEFAULT]: [member default_spin_us]). A refused value is
## reported naming it, and the servo does not start.
func start(rate_hz: float = 0.0, spin_us: float = SPIN_US_DEFAULT) -> bool:
	var started: bool = _backend.start(
		rate_hz if rate_hz > 0.0 else HapticServoConstants.DEFAULT_RATE_HZ,
		default_spin_us if spin_us == SPIN_US_DEFAULT else spin_us
	)
	changed.emit()
	return started


## Stops the servo thread; the device is left at zero force.
func stop() -> void:
	_backend.stop()
	changed.emit()


func is_running() -> bool:
	return _backend.is_running()


## One servo tick of [param dt] seconds on this thread (the thread must be stopped): a test
## or a headless match steps the servo itself, deterministically.
func step(dt: float) -> bool:
	return _backend.step(dt)


## "" while rendering is healthy, else why it stopped (e.g. the device was unplugged).
func get_status() -> String:
	return _backend.servo_status()


## The loop's statistics (rate, period and latency percentiles, real-time grants...).
func get_stats() -> HapticServoStats:
	return _backend.stats()


## The achieved rate in Hz, 0 when the servo is not running.
func get_rate_hz() -> float:
	return get_stats().achieved_rate_hz if is_running() else 0.0


## Up to [param max_samples] telemetry samples of [method get_telemetry_columns] floats
## each, oldest first, in device axes (y up); empty without the extension. Telemetry is off
## until a call turns it on (the [code]Haptics[/code] autoload turns it off at
## start: a game that never drains it is not counted drops).
func drain_telemetry(max_samples: int) -> PackedFloat32Array:
	if _backend.is_native():
		var settings: HapticServoSettings = _backend.servo_settings()
		if not settings.telemetry.enabled:
			settings.telemetry.enabled = true
			_backend.set_servo_settings(settings)
	return _backend.drain_telemetry(max_samples)


## The servo's settings now (the input mapping, the safety stage, the plane hold, telemetry;
## docs/values.md lists every field): a copy to read, or to change and hand to
## [method apply_settings]. The defaults without the extension.
func get_settings() -> HapticServoSettings:
	return _backend.servo_settings()


## Hands the servo [param settings] whole; refused ones are reported, naming the field, and
## change nothing.
func apply_settings(settings: HapticServoSettings) -> bool:
	var accepted: bool = _backend.set_servo_settings(settings)
	changed.emit()
	return accepted


## The names of a telemetry sample's floats, in order.
func get_telemetry_columns() -> PackedStringArray:
	return _backend.telemetry_columns()
