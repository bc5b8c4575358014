class_name PongServoLink
extends RefCounted
## A match's hold on the servo through [code]PongServo.shared()[/code]: the court size it sets
## (and gives back), the Pong renderer, the simulated hand, the servo thread (stopped while
## a stepped match runs it by hand), and the telemetry the peak force on the hand is read
## from. [method claim_court], then [method enter]; [method leave] gives everything back.

## The ball's air friction in beginner mode (the settings' own is the paper's, for play under
## gravity, where a falling ball gains speed): in the plane a ball only ever loses speed, and
## at the paper's friction a ball returned by a paddle held still stops before the net, out of
## everyone's reach, so a newcomer's gentle returns never reach the computer.
const BEGINNER_AIR_DECEL_M_PER_S2: float = 0.15

var _previous_players: int = -1
var _previous_air_decel: float = -1.0
var _stopped_servo: bool = false
var _telemetry_stride: int = 0
var _telemetry_total: int = -1
var _telemetry_capacity: int = 0


## Sets the servo's court to [param players] seats, with the beginner plane's air friction
## when [param beginner]; false (nothing changed) when refused.
func claim_court(players: int, beginner: bool = false) -> bool:
	var settings: PongSettings = PongServo.shared().get_settings()
	var configured: int = settings.players
	var air_decel: float = settings.air_linear_decel_m_per_s2
	settings.players = players
	if beginner:
		settings.air_linear_decel_m_per_s2 = minf(air_decel, BEGINNER_AIR_DECEL_M_PER_S2)
	if configured == players and settings.air_linear_decel_m_per_s2 == air_decel:
		return true
	if not PongServo.shared().apply_settings(settings):
		return false
	_previous_players = configured
	_previous_air_decel = air_decel
	return true


## Whether the open device can hold a paddle: present, not lost, with 3D input.
func device_usable() -> bool:
	if Haptics.device.get_id().is_empty() or Haptics.device.is_lost():
		return false
	return Haptics.device.get_capabilities().input_dof >= 3


## Whether the open device reports its stylus's orientation.
func device_has_orientation() -> bool:
	return Haptics.device.get_capabilities().has_orientation


## The Pong renderer on with no effect or event left over, the hand the game's, the
## servo thread stopped when [param stepped], the telemetry emptied.
func enter(stepped: bool) -> void:
	Haptics.hand_follows_input = false
	PongServo.shared().enter()
	if stepped and Haptics.servo.is_running():
		Haptics.servo.stop()
		_stopped_servo = true
	PongServo.shared().clear_effects()
	PongServo.shared().drain_events()
	var columns: PackedStringArray = Haptics.servo.get_telemetry_columns()
	_telemetry_stride = columns.size()
	_telemetry_total = columns.find("total_x")
	_telemetry_capacity = HapticServoConstants.TELEMETRY_QUEUE_CAPACITY
	Haptics.servo.drain_telemetry(_telemetry_capacity)


## Gives back what [method claim_court] and [method enter] took.
func leave() -> void:
	PongServo.shared().set_hand_target_3d(Vector3.ZERO)
	PongServo.shared().leave()
	if _previous_players > 0:
		var settings: PongSettings = PongServo.shared().get_settings()
		settings.players = _previous_players
		settings.air_linear_decel_m_per_s2 = _previous_air_decel
		PongServo.shared().apply_settings(settings)
	Haptics.hand_follows_input = true
	if _stopped_servo:
		Haptics.servo.start()


## The largest |force on the hand| (N, device space) of every servo tick since the last
## call, from the telemetry, and at least [param at_least]; just that while the servo
## thread does not run.
func peak_force(at_least: float) -> float:
	var peak: float = at_least
	if _telemetry_total < 0 or not Haptics.servo.is_running():
		return peak
	var samples: PackedFloat32Array = Haptics.servo.drain_telemetry(_telemetry_capacity)
	for i: int in range(_telemetry_total, samples.size() - 2, _telemetry_stride):
		peak = maxf(peak, Vector3(samples[i], samples[i + 1], samples[i + 2]).length())
	return peak
