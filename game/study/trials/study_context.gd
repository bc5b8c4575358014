class_name StudyContext
extends RefCounted
## What the practice and the maze trials are handed: the session, the stage, the
## [ConditionRig] that puts a condition into effect on the level shown, and the
## [StudyParticipant]. It loads a level under a condition and waits for the handle at the
## start; what it cannot do, it reports ([signal failed]) and the [StudyRunner] stops the
## study.

## A level or its condition could not be set up.
signal failed(error: String)
## The goal of the level shown was reached.
signal goal_reached

## Seconds the handle must stay in the start zone before the avatar may move.
const CENTRE_HOLD_S: float = 0.5

var session: StudySession = null
var rig: ConditionRig = null
## The stage while it is shown, else null (the runner sets it).
var stage: StudyStage = null
## Who takes part (the runner sets it; null: nobody steers the hand, as with a person).
var participant: StudyParticipant = null

var _centre_held: float = 0.0


func _init(p_session: StudySession, p_rig: ConditionRig) -> void:
	session = p_session
	rig = p_rig


## Shows [param scene] under [param condition] on the stage; false (and [signal failed])
## when the level or the condition cannot be set up.
func load_level(scene: PackedScene, condition: String) -> bool:
	rig.release()
	var level: StudyLevel = stage.show_level(scene) if scene != null else null
	if level == null:
		failed.emit("the level could not be loaded")
		return false
	level.goal_reached.connect(goal_reached.emit)
	rig.piloted = participant_steers()
	rig.pointer = stage.pointer_in_level
	if not rig.setup(level, condition, session.config.condition(condition)):
		failed.emit("the haptics servo refused the settings of the condition '%s'" % condition)
		return false
	if participant != null:
		participant.start_level(rig, false)
	return true


## Whether the [member participant] moves the hand itself ([method StudyParticipant.steer]).
func participant_steers() -> bool:
	return participant != null and participant.steers_hand()


## One physics tick of the avatar moving: a [member participant] that steers the hand moves
## it (a person moves the device).
func steer(delta: float) -> void:
	if participant_steers():
		rig.set_hand(participant.steer(rig, delta))


## The card that asks for the handle at the start position (the gauge shows where it is).
func show_centring() -> void:
	_centre_held = 0.0
	stage.gauge.tolerance = session.config.number("centre_tolerance")
	stage.gauge.target = rig.start_hand()
	stage.gauge.progress = 0.0
	stage.show_card("Hold still at the start", _centring_text(false), "", true)


## One tick of waiting for the handle at the start; true once it has been held there long
## enough.
func centre(delta: float) -> bool:
	var target: Vector2 = rig.start_hand()
	if participant_steers():
		rig.set_hand(target)
	var hand: Vector2 = rig.hand_position()
	var position_control: bool = StudyFormat.is_position_control(rig.condition)
	stage.show_hand(rig.map.point_of_hand(hand), position_control)
	var tolerance: float = session.config.number("centre_tolerance")
	var inside: bool = hand.distance_to(target) <= tolerance
	var settled: bool = rig.is_settled()
	if inside and settled:
		_centre_held += delta
	else:
		_centre_held = 0.0
	# In the zone but still pushed (a wall felt from the last trial): say so, or the card
	# seems not to notice a hand that is where the gauge asks for it.
	stage.card_body.text = _centring_text(inside and not settled)
	stage.gauge.hand = hand
	stage.gauge.progress = _centre_held / CENTRE_HOLD_S
	return _centre_held >= CENTRE_HOLD_S


func _centring_text(pushed: bool) -> String:
	if pushed:
		return "Hold the handle there, without pressing it anywhere, until the device's force eases."
	var practice: bool = session.phase == StudySession.Phase.PRACTICE
	return (
		"Bring the handle to the green zone of the gauge and hold it there; then %s."
		% ("you can move" if practice else "the trial begins")
	)


## Lets go of the level shown (the rig releases the condition; the stage clears).
func release_stage() -> void:
	rig.release()
	if stage != null:
		stage.clear_level()
