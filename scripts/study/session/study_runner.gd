class_name StudyRunner
extends Control
## The maze user study of the movement-based haptics paper, from the start screen to the
## thank-you, writing every record durably the moment it is complete ([StudyStore]).
##
## Flow: start screen (participant id, demographics, consent, researcher options) →
## practice on the demonstration levels until the participant presses Ready → for each
## condition in the participant's order (random from a recorded seed, or Latin square):
## its maze trial(s) (each: instructions, handle to the centre, then steer to the goal),
## then the six ratings → free text and favourite → done. An interrupted session is resumed
## from the start screen ("Resume participant") at the next trial, rating or final
## question; corrupt data is reported and never skipped ([ParticipantState]).
## [br][br]
## This node holds the session, the screen shown and the level being played; each step
## has its own child node: [SessionStart] (a new or resumed participant), [PracticeFlow],
## [TrialFlow] (the maze trials) and [AnswerFlow] (ratings, favourite, the end). Settings
## come from [StudyConfig]; the properties below override them (tests use their own study
## root). Run on its own, the scene reads the command line ([StudyLaunch]).

## The study was left (Back on the start screen, or the end).
signal closed
## The flow moved to [param new_phase].
signal phase_changed(new_phase: Phase)
## A maze trial ended and its record was written.
signal trial_recorded(result: TrialResult)

## Where the flow is.
enum Phase { START, PRACTICE, INTRO, CENTRING, TRIAL, ENDED, RATING, FINAL, DONE, STOPPED }

const START_SCENE: PackedScene = preload("res://scenes/study/start_screen.tscn")
const STAGE_SCENE: PackedScene = preload("res://scenes/study/stage.tscn")
## Thank-you and errors.
const MESSAGE_SCENE: PackedScene = preload("res://scenes/study/message_screen.tscn")
## Seconds the handle must stay in the start zone before a trial starts.
const CENTRE_HOLD_S: float = 0.5

## Study folder overriding the settings' (empty: the settings').
@export var study_root: String = ""
## Settings file merged over the defaults (empty: none).
@export var config_path: String = ""
## When not empty, a [ScriptedParticipant] with this id plays the session.
@export var scripted_participant: String = ""
## The scripted participant resumes instead of starting.
@export var scripted_resume: bool = false
## The scripted participant keeps still this long at the start of each trial, seconds.
@export var scripted_hold_s: float = 0.0
## Quit the program when the session ends.
@export var quit_when_done: bool = false
## Seconds the "Goal!" message shows before the next screen.
@export var pause_after_trial_s: float = 1.0

## The merged settings.
var config: StudyConfig = null
## Where the flow is; setting it emits [signal phase_changed].
var phase: Phase = Phase.START:
	set(value):
		phase = value
		phase_changed.emit(value)
## The current participant's writer (null before a session starts).
var store: StudyStore = null
## participant.json of the current session.
var meta: Dictionary = {}
## The current participant's condition order.
var condition_order: PackedStringArray = PackedStringArray()
## Index into [member condition_order] of the condition being run or rated.
var order_index: int = 0
## Trial records written so far, per condition.
var trial_counts: Dictionary[String, int] = {}
## Per condition, the next unused trial index.
var next_index: Dictionary[String, int] = {}
## Steer with [StudyPilot] (the scripted participant) instead of the mouse/keys.
var autopilot: bool = false
## The scripted participant's hand in the level shown (null until a level is loaded).
var pilot: StudyPilot = null
## The last resume report (problems and notes).
var report: PackedStringArray = PackedStringArray()
## The measures of the last trial recorded.
var last_result: TrialResult = null
## Puts the conditions into effect on the level shown.
var rig: ConditionRig = null

## The ratings, the final questions and the end of the session.
var answers: AnswerFlow = AnswerFlow.new()
var _screen: Control = null
var _stage: StudyStage = null
var _saved_haptics: Dictionary = {}
var _centre_held: float = 0.0
var _session_start: SessionStart = SessionStart.new()
var _practice: PracticeFlow = PracticeFlow.new()
var _trials: TrialFlow = TrialFlow.new()


func _ready() -> void:
	process_physics_priority = 10
	StudyTheme.apply(self)
	if get_tree().current_scene == self:
		var arguments: Dictionary = StudyLaunch.command_line()
		for property: String in arguments:
			set(property, arguments[property])
	config = StudyLaunch.load_config(config_path, study_root)
	for flow: Node in [_session_start, _practice, _trials, answers]:
		add_child(flow)
	_saved_haptics = ConditionRig.save_haptics()
	rig = ConditionRig.new()
	rig.name = "ConditionRig"
	add_child(rig)
	if not scripted_participant.is_empty():
		var script_node: ScriptedParticipant = ScriptedParticipant.new()
		script_node.name = "ScriptedParticipant"
		script_node.participant_id = scripted_participant
		script_node.resume = scripted_resume
		add_child(script_node)
		autopilot = true
		pause_after_trial_s = minf(pause_after_trial_s, 0.1)
	var refusal: String = StudyLaunch.refusal(config)
	if refusal.is_empty():
		show_start()
	else:
		for line: String in refusal.split("\n"):
			push_error("Maze study: " + line)
		show_message("The study cannot start", refusal, "Back", true)
		phase = Phase.STOPPED


func _exit_tree() -> void:
	if rig != null:
		rig.release()
	ConditionRig.restore_haptics(_saved_haptics)


func _physics_process(delta: float) -> void:
	match phase:
		Phase.PRACTICE:
			_practice.tick(delta)
		Phase.CENTRING:
			if centre(delta):
				_trials.begin_trial()
		Phase.TRIAL:
			_trials.tick(delta)


## The screen showing now ([StartScreen], [StudyStage], [RatingScreen], [FinalScreen] or
## [MessageScreen]).
func get_screen() -> Control:
	return _screen


## The stage while a level is shown, else null.
func get_stage() -> StudyStage:
	return _stage


## The condition being run or rated.
func current_condition() -> String:
	return condition_order[order_index] if order_index < condition_order.size() else ""


## What participants call the current condition ("Method 2 of 3"), never its id.
func method_heading() -> String:
	return "Method %d of %d" % [order_index + 1, condition_order.size()]


## Shows the start screen.
func show_start() -> void:
	var screen: StartScreen = show_screen(START_SCENE) as StartScreen
	var consent: PackedStringArray = StudyLaunch.consent(config)
	screen.set_consent_text(consent[0], consent[1])
	screen.set_data_folder(StudyStore.native_path(config.study_root()))
	var constraint: Dictionary = config.condition("constraint")
	screen.set_options(
		config.counterbalancing(), str(constraint["update"]), config.trials_per_condition()
	)
	screen.start_requested.connect(_session_start.start)
	screen.resume_requested.connect(_session_start.resume)
	screen.back_requested.connect(leave)
	phase = Phase.START


## Counts the trial of [param result], whose record has been written, and announces it.
func count_trial(result: TrialResult) -> void:
	trial_counts[result.condition] += 1
	trial_recorded.emit(result)


## Shows the first demonstration level (practice until the participant presses Ready).
func start_practice() -> void:
	_practice.start()


## Runs the condition at [param index] of the order: its remaining trials, then its ratings.
func begin_condition(index: int) -> void:
	order_index = index
	if trial_counts[current_condition()] >= config.trials_per_condition():
		answers.show_rating()
	else:
		_trials.show_intro()


## The stage, shown if it is not showing yet.
func use_stage() -> StudyStage:
	if _stage != null and _screen == _stage:
		return _stage
	_stage = show_screen(STAGE_SCENE) as StudyStage
	_stage.start_pressed.connect(_trials.on_start_pressed)
	_stage.next_level_pressed.connect(_practice.on_next_level_pressed)
	_stage.next_condition_pressed.connect(_practice.on_next_condition_pressed)
	_stage.ready_pressed.connect(_practice.on_ready_pressed)
	return _stage


## Shows [param scene] under [param condition] on the stage; false (and the study stops)
## when the level or the condition cannot be set up.
func load_level(scene: PackedScene, condition: String) -> bool:
	rig.release()
	var level: StudyLevel = _stage.show_level(scene) if scene != null else null
	if level == null:
		fatal("the level could not be loaded")
		return false
	level.goal_reached.connect(_on_goal_reached)
	var settings: Dictionary = config.condition(condition)
	rig.piloted = autopilot
	rig.pointer = _stage.pointer_in_level
	if not rig.setup(level, condition, settings):
		fatal("the haptics server refused the settings of the condition '%s'" % condition)
		return false
	if autopilot:
		pilot = StudyPilot.new(level.get_autopilot_path(), config.number("autopilot_speed"))
	return true


## The card that asks for the handle at the start position (the gauge shows where it is).
func show_centring() -> void:
	_centre_held = 0.0
	_stage.gauge.tolerance = config.number("centre_tolerance")
	_stage.gauge.target = rig.start_hand()
	_stage.gauge.progress = 0.0
	var then: String = "the trial begins" if phase != Phase.PRACTICE else "you can move"
	_stage.show_card(
		"Hold still at the start",
		"Bring the handle to the green zone of the gauge and hold it there; then %s." % then,
		"",
		true
	)


## One tick of waiting for the handle at the start; true once it has been held there long
## enough.
func centre(delta: float) -> bool:
	var target: Vector2 = rig.start_hand()
	if autopilot:
		rig.set_hand(target)
	var hand: Vector2 = rig.hand_position()
	var position_control: bool = ConditionRig.is_position_control(rig.condition)
	_stage.show_hand(rig.map.point_of_hand(hand), position_control)
	if hand.distance_to(target) <= config.number("centre_tolerance") and rig.is_settled():
		_centre_held += delta
	else:
		_centre_held = 0.0
	_stage.gauge.hand = hand
	_stage.gauge.progress = _centre_held / CENTRE_HOLD_S
	return _centre_held >= CENTRE_HOLD_S


## Lets go of the level shown (the rig releases the condition; the stage clears).
func release_stage() -> void:
	rig.release()
	if _stage != null:
		_stage.clear_level()


## Replaces the screen shown with a new instance of [param scene].
func show_screen(scene: PackedScene) -> Control:
	if _screen != null:
		if _screen == _stage:
			release_stage()
			_stage = null
		remove_child(_screen)
		_screen.queue_free()
	_screen = scene.instantiate() as Control
	add_child(_screen)
	return _screen


## Shows a [MessageScreen]; its button leaves the study.
func show_message(heading: String, body: String, button: String, is_error: bool = false) -> void:
	var screen: MessageScreen = show_screen(MESSAGE_SCENE) as MessageScreen
	screen.show_message(heading, body, button, is_error)
	screen.closed.connect(leave)


## A write failed: the session stops; what was written before is safe.
func fatal(error: String) -> void:
	push_error("Maze study stopped: " + error)
	var who: String = store.participant_id if store != null else "the participant"
	show_message(
		"The study stopped",
		(
			(
				"%s\n\nEverything recorded before this point is saved. Fix the problem, then "
				+ 'choose "Resume participant" for %s to continue where the session stopped.'
			)
			% [error, who]
		),
		"Back",
		true
	)
	phase = Phase.STOPPED


## Leaves the study: quits when the scene runs on its own, else emits [signal closed].
func leave() -> void:
	if is_standalone():
		CleanExit.quit(0)
	else:
		closed.emit()


## Whether the study scene is the program's main scene.
func is_standalone() -> bool:
	return is_inside_tree() and get_tree().current_scene == self


func _on_goal_reached() -> void:
	if phase == Phase.TRIAL:
		_trials.end_trial(true)
	elif phase == Phase.PRACTICE:
		_practice.on_goal_reached()
