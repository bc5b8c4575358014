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
## This node shows the screens and decides which step comes next; each step has its own
## child node, handed the [StudySession] (and the stage, the [StudyContext]) and reporting
## back by signal: [SessionStart] (a new or resumed participant), [PracticeFlow],
## [TrialFlow] (the maze trials) and [AnswerFlow] (ratings, favourite, the end). Settings
## come from [StudyConfig]; the properties below override them (tests use their own study
## root). Run on its own, the scene reads the command line ([StudyLaunch]). Who takes part
## is the [member participant]: a person at these screens, unless a test driver gives its own.

## The study was left (Back on the start screen, or the end).
signal closed
## The flow moved to [param new_phase].
signal phase_changed(new_phase: StudySession.Phase)
## A maze trial ended and its record was written.
signal trial_recorded(result: TrialResult)
## [param screen] is shown now (the [member participant] is told too).
signal screen_shown(screen: Control)

const START_SCENE: PackedScene = preload("res://game/study/screens/start_screen.tscn")
const STAGE_SCENE: PackedScene = preload("res://game/study/screens/stage.tscn")
## Thank-you and errors.
const MESSAGE_SCENE: PackedScene = preload("res://game/study/screens/message_screen.tscn")
const RATING_SCENE: PackedScene = preload("res://game/study/screens/rating_screen.tscn")
const FINAL_SCENE: PackedScene = preload("res://game/study/screens/final_screen.tscn")

## Study folder overriding the settings' (empty: the settings').
@export var study_root: String = ""
## Settings file merged over the defaults (empty: none).
@export var config_path: String = ""
## Seconds the "Goal!" message shows before the next screen.
@export var pause_after_trial_s: float = 1.0

## The participant's session, shared with the steps.
var session: StudySession = StudySession.new()
## The merged settings.
var config: StudyConfig:
	get:
		return session.config
## Where the flow is.
var phase: StudySession.Phase:
	get:
		return session.phase
## The last resume report (problems and notes).
var report: PackedStringArray:
	get:
		return session.report
## Who takes part: null (the default) stands for a person at these screens and the device
## (a plain [StudyParticipant]); a test driver sets its own before the runner enters the
## tree.
var participant: StudyParticipant = null

var _screen: Control = null
var _saved_haptics: Dictionary = {}
# Puts the conditions into effect on the level shown.
var _rig: ConditionRig = ConditionRig.new()
var _context: StudyContext = StudyContext.new(session, _rig)
var _session_start: SessionStart = SessionStart.new()
var _practice: PracticeFlow = PracticeFlow.new()
var _trials: TrialFlow = TrialFlow.new()
var _answers: AnswerFlow = AnswerFlow.new()


func _ready() -> void:
	process_physics_priority = 10
	StudyTheme.apply(self)
	if get_tree().current_scene == self:
		var arguments: Dictionary = StudyLaunch.command_line()
		for property: String in arguments:
			set(property, arguments[property])
	session.config = StudyLaunch.load_config(config_path, study_root)
	_saved_haptics = ConditionRig.save_haptics()
	_rig.name = "ConditionRig"
	add_child(_rig)
	if participant == null:
		participant = StudyParticipant.new()
	participant.name = "Participant"
	add_child(participant)
	_context.participant = participant
	participant.join(session)
	screen_shown.connect(participant.show_screen)
	session.phase_changed.connect(phase_changed.emit)
	_connect_steps()
	var refusal: String = StudyLaunch.refusal(config)
	if refusal.is_empty():
		show_start()
	else:
		for line: String in refusal.split("\n"):
			push_error("Maze study: " + line)
		show_message("The study cannot start", refusal, "Back", true)
		session.phase = StudySession.Phase.STOPPED


func _exit_tree() -> void:
	_rig.release()
	ConditionRig.restore_haptics(_saved_haptics)


func _physics_process(delta: float) -> void:
	match session.phase:
		StudySession.Phase.PRACTICE:
			_practice.tick(delta)
		StudySession.Phase.CENTRING:
			_trials.centre(delta)
		StudySession.Phase.TRIAL:
			_trials.tick(delta)


## The screen showing now ([StartScreen], [StudyStage], [RatingScreen], [FinalScreen] or
## [MessageScreen]).
func get_screen() -> Control:
	return _screen


## The stage while a level is shown, else null.
func get_stage() -> StudyStage:
	return _context.stage


## The condition being run or rated.
func current_condition() -> String:
	return session.current_condition()


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
	session.phase = StudySession.Phase.START


## Shows the first demonstration level (practice until the participant presses Ready).
func start_practice() -> void:
	_use_stage()
	_practice.start()


## Runs the condition at [param index] of the order: its remaining trials, then its ratings.
func begin_condition(index: int) -> void:
	session.order_index = index
	if session.trial_counts[current_condition()] >= config.trials_per_condition():
		show_rating()
	else:
		_use_stage()
		_trials.show_intro()


## Asks for the six ratings of the current condition.
func show_rating() -> void:
	_context.release_stage()
	_answers.ask_ratings(show_screen(RATING_SCENE) as RatingScreen)


## Asks for the differences felt and the favourite.
func show_final() -> void:
	_context.release_stage()
	_answers.ask_final(show_screen(FINAL_SCENE) as FinalScreen)


## Replaces the screen shown with a new instance of [param scene].
func show_screen(scene: PackedScene) -> Control:
	if _screen != null:
		if _screen == _context.stage:
			_context.release_stage()
			_context.stage = null
		remove_child(_screen)
		_screen.queue_free()
	_screen = scene.instantiate() as Control
	add_child(_screen)
	screen_shown.emit(_screen)
	return _screen


## Shows a [MessageScreen]; its button leaves the study.
func show_message(heading: String, body: String, button: String, is_error: bool = false) -> void:
	var screen: MessageScreen = show_screen(MESSAGE_SCENE) as MessageScreen
	screen.show_message(heading, body, button, is_error)
	screen.closed.connect(leave)


## A write failed: the session stops; what was written before is safe.
func fatal(error: String) -> void:
	push_error("Maze study stopped: " + error)
	var who: String = session.store.participant_id if session.store != null else "the participant"
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
	session.phase = StudySession.Phase.STOPPED


## Leaves the study: quits when the scene runs on its own, else emits [signal closed].
func leave() -> void:
	if is_standalone():
		CleanExit.quit(0)
	else:
		closed.emit()


## Whether the study scene is the program's main scene.
func is_standalone() -> bool:
	return is_inside_tree() and get_tree().current_scene == self


# Each step is handed what it works with; its signals say what comes next.
func _connect_steps() -> void:
	_session_start.setup(session)
	_practice.setup(_context)
	_trials.setup(_context, pause_after_trial_s)
	_answers.setup(session)
	for step: Node in [_session_start, _practice, _trials, _answers]:
		add_child(step)
	_session_start.started.connect(_on_session_started)
	_session_start.refused.connect(_on_start_refused)
	_practice.finished.connect(func() -> void: begin_condition(session.order_index))
	_trials.trial_recorded.connect(trial_recorded.emit)
	_trials.trials_done.connect(show_rating)
	_answers.rated.connect(_on_rated)
	_answers.finished.connect(_on_finished)
	_context.goal_reached.connect(_on_goal_reached)
	_context.failed.connect(fatal)
	_trials.failed.connect(fatal)
	_answers.failed.connect(fatal)


# The stage, shown if it is not showing yet.
func _use_stage() -> void:
	if _context.stage != null and _screen == _context.stage:
		return
	var stage: StudyStage = show_screen(STAGE_SCENE) as StudyStage
	stage.start_pressed.connect(_trials.on_start_pressed)
	stage.next_level_pressed.connect(_practice.on_next_level_pressed)
	stage.next_condition_pressed.connect(_practice.on_next_condition_pressed)
	stage.ready_pressed.connect(_practice.on_ready_pressed)
	_context.stage = stage


func _on_session_started(step: ParticipantState.Step) -> void:
	match step:
		ParticipantState.Step.PRACTICE:
			start_practice()
		ParticipantState.Step.TRIALS:
			begin_condition(session.order_index)
		ParticipantState.Step.RATING:
			show_rating()
		ParticipantState.Step.FINAL:
			show_final()
		ParticipantState.Step.FINISH:
			_answers.finish_session()


func _on_start_refused(problem: String) -> void:
	(_screen as StartScreen).show_problem(problem)


func _on_rated(order_index: int) -> void:
	if order_index + 1 < session.condition_order.size():
		begin_condition(order_index + 1)
	else:
		show_final()


func _on_finished() -> void:
	var store: StudyStore = session.store
	show_message(
		"Thank you!",
		(
			"The session of %s is complete and saved in %s."
			% [store.participant_id, StudyStore.native_path(store.folder())]
		),
		"Back to menu" if not is_standalone() else "Quit"
	)
	session.phase = StudySession.Phase.DONE


func _on_goal_reached() -> void:
	if session.phase == StudySession.Phase.TRIAL:
		_trials.end_trial(true)
	elif session.phase == StudySession.Phase.PRACTICE:
		_practice.on_goal_reached()
