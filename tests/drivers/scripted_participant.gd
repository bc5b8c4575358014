class_name ScriptedParticipant
extends StudyParticipant
## Plays a whole study session through the real screens, as a participant and researcher
## would (fields filled, buttons pressed), for tests and unattended demonstrations
## ([code]study_scripted.tscn[/code] beside it). Given to a [StudyRunner] with
## [method take_part_in], it is handed the session ([method join]) and each screen
## ([method show_screen]), and steers the simulated hand in the levels with a [StudyPilot]
## ([method steer]). Ratings, and unless told otherwise the demographics and the favourite
## ([method profile_of]), are drawn from generators seeded with the id, so a run is
## reproducible and a study of several scripted participants varies as real ones do.

## Emitted when the session ended (the thank-you is showing).
signal finished

## How many methods a drawn favourite names, each entry equally likely: none (abstains),
## one (three times as often) or two.
const FAVOURITE_COUNTS: Array[int] = [0, 1, 1, 1, 2]
## Longest "Goal!" pause after a trial in a scripted session, seconds.
const PAUSE_AFTER_TRIAL_S: float = 0.1

## Id to start (or resume).
var participant_id: String = "SCRIPTED"
## Resume [member participant_id] instead of starting it.
var resume: bool = false
## Demographics entered on the start screen; empty: [method profile_of]'s.
var demographics: Dictionary = {}
## Seconds spent on each demonstration level / condition before moving on.
var practice_seconds: float = 0.4
## Favourite conditions by presentation position (0-based; "Method 1" is 0), used when
## [member draw_favourite] is off.
var favourite: PackedInt32Array = PackedInt32Array()
## Take the favourite from [method profile_of] instead of [member favourite].
var draw_favourite: bool = true
## Free text entered at the end.
var differences_text: String = "Scripted run: the methods felt different."
## Fill in and press through the screens (off: only the hand is scripted, and whoever drives
## the runner answers the screens).
var plays_screens: bool = true
## Seconds to keep still at the start of each trial (lets tests act mid-trial).
var hold_s: float = 0.0
## Push into the walls around the start of each trial (and through them in position
## control) before heading for the goal ([member StudyPilot.touch_walls]).
var touch_walls: bool = false
## The hand in the level shown (null until a level is set up).
var pilot: StudyPilot = null

var _session: StudySession = null
var _screen: Control = null
var _rng: RandomNumberGenerator = RandomNumberGenerator.new()
var _practice_steps: int = -1
var _practice_left: float = 0.0


func _init(id: String = "SCRIPTED", p_resume: bool = false) -> void:
	participant_id = id
	resume = p_resume
	name = "ScriptedParticipant"


## Takes part in [param study] (before it enters the tree), with a short "Goal!" pause.
func take_part_in(study: StudyRunner) -> void:
	study.participant = self
	study.pause_after_trial_s = minf(study.pause_after_trial_s, PAUSE_AFTER_TRIAL_S)


## Plays the session [param session] from its current screen on.
func join(session: StudySession) -> void:
	_session = session
	_rng.seed = hash(participant_id)
	var profile: Dictionary = profile_of(participant_id)
	if demographics.is_empty():
		demographics = profile["demographics"]
	if draw_favourite:
		favourite = profile["favourite"]
	_session.phase_changed.connect(_on_phase_changed)
	if _session.phase == StudySession.Phase.START and _screen is StartScreen:
		_on_phase_changed.call_deferred(StudySession.Phase.START)


func steers_hand() -> bool:
	return true


func start_level(rig: ConditionRig, trial: bool) -> void:
	var speed: float = _session.config.number("autopilot_speed")
	pilot = StudyPilot.new(rig.level.get_autopilot_path(), speed)
	if trial:
		pilot.hold_s = hold_s
		pilot.touch_walls = touch_walls


func steer(rig: ConditionRig, delta: float) -> Vector2:
	return pilot.steer(rig, delta) if pilot != null else rig.start_hand()


## What scripted participant [param id] answers when not told: [code]demographics[/code]
## (each key of the schema's demographics, a value drawn from its values) and
## [code]favourite[/code] (presentation positions, ascending; as many as
## [constant FAVOURITE_COUNTS] draws), from a generator seeded with the id.
static func profile_of(id: String) -> Dictionary:
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = hash("profile:" + id)
	var drawn: Dictionary = {}
	for key: String in StudyFormat.demographic_keys():
		var values: PackedStringArray = StudyFormat.demographic_values(key)
		drawn[key] = values[rng.randi_range(0, values.size() - 1)]
	var count: int = FAVOURITE_COUNTS[rng.randi_range(0, FAVOURITE_COUNTS.size() - 1)]
	var positions: Array[int] = []
	for i: int in StudyFormat.conditions.size():
		positions.append(i)
	var chosen: PackedInt32Array = PackedInt32Array()
	for _pick: int in count:
		var position: int = positions.pop_at(rng.randi_range(0, positions.size() - 1))
		chosen.append(position)
	chosen.sort()
	return {"demographics": drawn, "favourite": chosen}


## The runner shows [param screen] now.
func show_screen(screen: Control) -> void:
	_screen = screen


func _on_phase_changed(phase: StudySession.Phase) -> void:
	if phase == StudySession.Phase.DONE:
		finished.emit()
	if not plays_screens:
		return
	match phase:
		StudySession.Phase.START:
			_fill_start.call_deferred()
		StudySession.Phase.PRACTICE:
			_practise()
		StudySession.Phase.INTRO:
			_press_start.call_deferred()
		StudySession.Phase.RATING:
			_rate.call_deferred()
		StudySession.Phase.FINAL:
			_answer_final.call_deferred()


func _fill_start() -> void:
	var screen: StartScreen = _screen as StartScreen
	if screen == null:
		return
	screen.id_edit.text = participant_id
	if resume:
		screen.resume_button.pressed.emit()
		return
	for key: String in demographics:
		screen.set_demographic(key, str(demographics[key]))
	screen.consent_check.button_pressed = true
	screen.start_button.pressed.emit()


# Tries the next condition, then the next level, then says ready, practice_seconds apart.
func _practise() -> void:
	_practice_steps = 0
	_practice_left = practice_seconds


func _process(delta: float) -> void:
	if _practice_steps < 0 or _session == null or _session.phase != StudySession.Phase.PRACTICE:
		return
	_practice_left -= delta
	if _practice_left > 0.0:
		return
	_practice_left = practice_seconds
	var stage: StudyStage = _screen as StudyStage
	match _practice_steps:
		0:
			stage.next_condition_pressed.emit()
		1:
			stage.next_level_pressed.emit()
		_:
			_practice_steps = -1
			stage.ready_button.pressed.emit()
			return
	_practice_steps += 1


func _press_start() -> void:
	var stage: StudyStage = _screen as StudyStage
	if _still(stage, StudySession.Phase.INTRO):
		stage.start_button.pressed.emit()


func _rate() -> void:
	var screen: RatingScreen = _screen as RatingScreen
	if screen == null:
		return
	for criterion: String in StudyFormat.criteria:
		screen.set_rating(
			criterion, _rng.randi_range(StudyFormat.rating_min, StudyFormat.rating_max)
		)
	screen.submit_button.pressed.emit()


func _answer_final() -> void:
	var screen: FinalScreen = _screen as FinalScreen
	if screen == null:
		return
	screen.text_edit.text = differences_text
	screen.set_favourite(favourite)
	screen.submit_button.pressed.emit()


func _still(stage: StudyStage, phase: StudySession.Phase) -> bool:
	return is_instance_valid(stage) and is_inside_tree() and _session.phase == phase
