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
## Settings come from [StudyConfig]; the properties below override them (tests use their
## own study root). Run on its own, the scene reads the command line after [code]--[/code]:
## [codeblock]
## --study-root=PATH          study folder (default: the config's, user://study)
## --study-config=PATH        extra settings file merged over the defaults
## --scripted-participant=ID  a ScriptedParticipant plays the whole session (tests, demos)
## --resume                   the scripted participant resumes ID instead of starting it
## --hold=SECONDS             the scripted participant waits this long in each trial
## --quit-when-done           quit when the session ends (exit code 0)
## [/codeblock]

## The study was left (Back on the start screen, or the end).
signal closed
## The flow moved to [param new_phase].
signal phase_changed(new_phase: Phase)
## A maze trial ended and its record was written.
signal trial_recorded(result: TrialResult)

## Where the flow is.
enum Phase { START, PRACTICE, INTRO, CENTRING, TRIAL, ENDED, RATING, FINAL, DONE, STOPPED }

## The start screen.
const START_SCENE: PackedScene = preload("res://scenes/study/start_screen.tscn")
## Where levels are played.
const STAGE_SCENE: PackedScene = preload("res://scenes/study/stage.tscn")
## The six criteria.
const RATING_SCENE: PackedScene = preload("res://scenes/study/rating_screen.tscn")
## Free text and favourite.
const FINAL_SCENE: PackedScene = preload("res://scenes/study/final_screen.tscn")
## Thank-you and errors.
const MESSAGE_SCENE: PackedScene = preload("res://scenes/study/message_screen.tscn")
## The consent text shipped with the game; a [code]consent.txt[/code] in the study folder
## replaces it.
const DEFAULT_CONSENT_PATH: String = "res://assets/study/consent.txt"
## Seconds the handle must stay in the start zone before a trial starts.
const CENTRE_HOLD_S: float = 0.5
## What the participant is asked to do in the maze.
const TASK_TEXT: String = (
	"Steer the submarine from the centre of the maze to the flag in the lower right. "
	+ "You will bump into walls on the way; that is part of it."
)

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
## Where the flow is.
var phase: Phase = Phase.START
## The current participant's writer (null before a session starts).
var store: StudyStore = null
## participant.json of the current session.
var meta: Dictionary = {}
## The current participant's condition order.
var condition_order: PackedStringArray = PackedStringArray()
## Index into [member condition_order] of the condition being run or rated.
var order_index: int = 0
## Steer with [StudyPilot] (the scripted participant) instead of the mouse/keys.
var autopilot: bool = false
## The last resume report (problems and notes).
var report: PackedStringArray = PackedStringArray()
## The measures of the last trial recorded.
var last_result: TrialResult = null

var _screen: Control = null
var _stage: StudyStage = null
var _rig: ConditionRig = null
var _recorder: TrialRecorder = null
var _pilot: StudyPilot = null
var _saved_haptics: Dictionary = {}
var _trial_counts: Dictionary[String, int] = {}
var _next_index: Dictionary[String, int] = {}
var _practice_level: int = 0
var _practice_method: int = 0
var _practice_live: bool = false
var _ticks: int = 0
var _centre_held: float = 0.0
var _maze: PackedScene = null


func _ready() -> void:
	process_physics_priority = 10
	StudyTheme.apply(self)
	if get_tree().current_scene == self:
		_read_command_line()
	config = _load_config()
	_saved_haptics = ConditionRig.save_haptics()
	_rig = ConditionRig.new()
	_rig.name = "ConditionRig"
	add_child(_rig)
	if not scripted_participant.is_empty():
		var script_node: ScriptedParticipant = ScriptedParticipant.new()
		script_node.name = "ScriptedParticipant"
		script_node.participant_id = scripted_participant
		script_node.resume = scripted_resume
		add_child(script_node)
		autopilot = true
		pause_after_trial_s = minf(pause_after_trial_s, 0.1)
	var refusal: String = _refusal()
	if refusal.is_empty():
		show_start()
	else:
		for line: String in refusal.split("\n"):
			push_error("Maze study: " + line)
		_show_message("The study cannot start", refusal, "Back", true)
		_set_phase(Phase.STOPPED)


func _exit_tree() -> void:
	if _rig != null:
		_rig.release()
	ConditionRig.restore_haptics(_saved_haptics)


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


## The study folder in use.
func get_study_root() -> String:
	return config.study_root()


## Shows the start screen.
func show_start() -> void:
	var screen: StartScreen = _show_screen(START_SCENE) as StartScreen
	var consent: PackedStringArray = _consent()
	screen.set_consent_text(consent[0], consent[1])
	screen.set_data_folder(StudyStore.native_path(config.study_root()))
	var constraint: Dictionary = config.condition("constraint")
	screen.set_options(
		config.counterbalancing(), str(constraint["update"]), config.trials_per_condition()
	)
	screen.start_requested.connect(_on_start_requested)
	screen.resume_requested.connect(_on_resume_requested)
	screen.back_requested.connect(_leave)
	_set_phase(Phase.START)


func _physics_process(delta: float) -> void:
	match phase:
		Phase.PRACTICE:
			if not _practice_live:
				if _centre(delta):
					_practice_live = true
					_rig.go()
					_stage.hide_card()
					_stage.show_hand(Vector2.ZERO, false)
			elif autopilot and _pilot != null:
				_rig.set_hand(_pilot.steer(_rig, delta))
		Phase.CENTRING:
			if _centre(delta):
				_begin_trial()
		Phase.TRIAL:
			_trial_tick(delta)


# ---------------------------------------------------------------------------- start


func _on_start_requested(id: String, demographics: Dictionary, options: Dictionary) -> void:
	var screen: StartScreen = _screen as StartScreen
	_apply_options(options)
	var candidate: StudyStore = StudyStore.new(config.study_root(), id)
	if candidate.has_data():
		screen.show_problem(
			(
				(
					'Participant %s already has data in %s. Choose "Resume participant" to '
					+ "continue their session, or enter another ID."
				)
				% [id, StudyStore.native_path(candidate.folder())]
			)
		)
		return
	var order_seed: int = (
		config.order_seed() if config.order_seed() >= 0 else ConditionOrder.new_seed()
	)
	var mode: String = str(options.get("counterbalancing", config.counterbalancing()))
	var order: PackedStringArray = ConditionOrder.random_order(order_seed)
	var number: int = StudyStore.participant_ids(config.study_root()).size()
	if mode == "latin_square":
		order = ConditionOrder.latin_square_order(number)
	meta = {
		"format_version": StudyFormat.FORMAT_VERSION,
		"participant_id": id,
		"demographics": demographics,
		"seed": order_seed,
		"condition_order": Array(order),
		"counterbalancing": mode,
		"app_version": _app_version(),
		"extension_version": Haptics.get_version(),
		"started": StudyFormat.timestamp(),
		"finished": null,
		"participant_number": number,
		"constraint_update": str(config.condition("constraint")["update"]),
		"trials_per_condition": config.trials_per_condition(),
	}
	if not candidate.create(meta):
		screen.show_problem("Could not create the participant's data: %s" % candidate.last_error)
		push_error("Maze study: " + candidate.last_error)
		return
	store = candidate
	condition_order = order
	for condition: String in StudyFormat.CONDITIONS:
		_trial_counts[condition] = 0
		_next_index[condition] = 0
	start_practice()


func _on_resume_requested(id: String, options: Dictionary) -> void:
	var screen: StartScreen = _screen as StartScreen
	_apply_options(options)
	var state: ParticipantState = ParticipantState.scan(config.study_root(), id)
	report = state.report_lines()
	if not state.problems.is_empty():
		for problem: String in state.problems:
			push_error("Maze study data problem: " + problem)
		screen.show_problem(
			(
				(
					"Cannot resume %s: the data has problems (nothing was changed; fix or move "
					+ "the files, then resume):\n%s"
				)
				% [id, "\n".join(state.problems)]
			)
		)
		return
	if not state.exists:
		screen.show_problem(
			"There is no data for %s in %s: nothing to resume." % [id, config.study_root()]
		)
		return
	for note: String in state.notes:
		print("Maze study: resume %s: %s" % [id, note])
	store = StudyStore.new(config.study_root(), id)
	meta = state.meta
	condition_order = state.condition_order
	_trial_counts = state.trial_counts
	_next_index = state.next_index
	var next: Dictionary = state.next_step(config.trials_per_condition())
	var step: ParticipantState.Step = next["step"]
	order_index = next["order_index"]
	match step:
		ParticipantState.Step.PRACTICE:
			start_practice()
		ParticipantState.Step.TRIALS:
			if config.practice_on_resume():
				start_practice()
			else:
				begin_condition(order_index)
		ParticipantState.Step.RATING:
			_show_rating()
		ParticipantState.Step.FINAL:
			_show_final()
		ParticipantState.Step.FINISH:
			_finish_session()
		ParticipantState.Step.DONE:
			screen.show_problem("%s has finished the study: there is nothing to resume." % id)


# ---------------------------------------------------------------------------- practice


## Shows the first demonstration level (practice until the participant presses Ready).
func start_practice() -> void:
	_use_stage()
	_practice_level = 0
	_practice_method = 0
	_stage.show_practice_controls(true)
	_set_phase(Phase.PRACTICE)
	_load_practice()


func _load_practice() -> void:
	var levels: PackedStringArray = config.demo_levels()
	var methods: PackedStringArray = config.practice_conditions()
	if levels.is_empty() or methods.is_empty():
		_on_ready_pressed()
		return
	var scene: PackedScene = load(levels[_practice_level % levels.size()]) as PackedScene
	var condition: String = methods[_practice_method % methods.size()]
	if not _load_level(scene, condition):
		return
	_practice_live = false
	_show_centring()
	var letter: String = char(65 + _practice_method % methods.size())
	_stage.set_status(
		"Practice: %s  ·  control %s of %d" % [_stage.level.title, letter, methods.size()],
		'Explore, bump into the walls, reach the flag. Press "I\'m ready" when comfortable.'
	)


func _on_next_level_pressed() -> void:
	if phase == Phase.PRACTICE:
		_practice_level += 1
		_load_practice()


func _on_next_method_pressed() -> void:
	if phase == Phase.PRACTICE:
		_practice_method += 1
		_load_practice()


func _on_ready_pressed() -> void:
	if phase == Phase.PRACTICE:
		begin_condition(order_index)


# ---------------------------------------------------------------------------- trials


## Runs the condition at [param index] of the order: its remaining trials, then its ratings.
func begin_condition(index: int) -> void:
	order_index = index
	if _trial_counts[current_condition()] >= config.trials_per_condition():
		_show_rating()
	else:
		_show_intro()


func _show_intro() -> void:
	_use_stage()
	_stage.show_practice_controls(false)
	if not _load_level(_maze_scene(), current_condition()):
		return
	var done: int = _trial_counts[current_condition()]
	var total: int = config.trials_per_condition()
	var heading: String = "Method %d of %d" % [order_index + 1, condition_order.size()]
	var trial_text: String = "Trial %d of %d" % [done + 1, total] if total > 1 else ""
	_stage.set_status(heading, trial_text if not trial_text.is_empty() else "The maze")
	var body: String = TASK_TEXT
	if not trial_text.is_empty():
		body = "%s. %s" % [trial_text, TASK_TEXT]
	_stage.show_card(heading, body, "Start", false)
	_set_phase(Phase.INTRO)


func _on_stage_start_pressed() -> void:
	if phase != Phase.INTRO:
		return
	_show_centring()
	_set_phase(Phase.CENTRING)


# The card that asks for the handle at the start position (the gauge shows where it is).
func _show_centring() -> void:
	_centre_held = 0.0
	_stage.gauge.tolerance = config.centre_tolerance()
	_stage.gauge.target = _rig.start_hand()
	_stage.gauge.progress = 0.0
	var then: String = "the trial begins" if phase != Phase.PRACTICE else "you can move"
	_stage.show_card(
		"Hold still at the start",
		"Bring the handle to the green zone of the gauge and hold it there; then %s." % then,
		"",
		true
	)


# One tick of waiting for the handle at the start; true once it has been held there long
# enough.
func _centre(delta: float) -> bool:
	var target: Vector2 = _rig.start_hand()
	if autopilot:
		_rig.set_hand(target)
	var hand: Vector2 = _rig.hand_position()
	var position_control: bool = ConditionRig.is_position_control(_rig.condition)
	_stage.show_hand(_rig.map.point_of_hand(hand), position_control)
	if hand.distance_to(target) <= config.centre_tolerance() and _rig.is_settled():
		_centre_held += delta
	else:
		_centre_held = 0.0
	_stage.gauge.hand = hand
	_stage.gauge.progress = _centre_held / CENTRE_HOLD_S
	return _centre_held >= CENTRE_HOLD_S


func _begin_trial() -> void:
	var condition: String = current_condition()
	var index: int = _next_index[condition]
	_next_index[condition] = index + 1
	var level: StudyLevel = _stage.level
	var stiffness: float = config.condition(condition).get("stiffness", 0.0)
	_recorder = TrialRecorder.new(store, condition, level.level_id, index, _rig.map, stiffness)
	_recorder.decimation = config.telemetry_decimation()
	_recorder.flush_s = config.telemetry_flush_s()
	_recorder.contact_gap_s = config.contact_gap_s()
	_rig.go()
	if not _recorder.begin(_rig.avatar_position()):
		_fatal(_recorder.error)
		return
	_pilot = StudyPilot.new(level.get_autopilot_path(), config.autopilot_speed())
	_pilot.hold_s = scripted_hold_s
	_ticks = 0
	_stage.hide_card()
	_stage.show_hand(Vector2.ZERO, false)
	_set_phase(Phase.TRIAL)


func _trial_tick(delta: float) -> void:
	_ticks += 1
	if autopilot and _pilot != null:
		_rig.set_hand(_pilot.steer(_rig, delta))
	if not _recorder.tick(_rig.avatar_position(), delta):
		_fatal(_recorder.error)
		return
	if _ticks * delta >= config.trial_timeout_s():
		_end_trial(false)


func _end_trial(completed: bool) -> void:
	if phase != Phase.TRIAL:
		return
	var time_s: float = float(_ticks) / Engine.physics_ticks_per_second
	_rig.hold()
	if not _recorder.finish(_rig.avatar_position(), time_s, completed):
		_fatal(_recorder.error)
		return
	last_result = _recorder.result
	if not store.append_trial(last_result):
		_fatal(store.last_error)
		return
	_recorder = null
	var condition: String = current_condition()
	_trial_counts[condition] += 1
	trial_recorded.emit(last_result)
	_set_phase(Phase.ENDED)
	_stage.toast("Goal!" if completed else "Time is up")
	# A timer calling back (not an await): if the study is closed meanwhile, nothing runs.
	get_tree().create_timer(pause_after_trial_s).timeout.connect(_after_trial.bind(condition))


func _after_trial(condition: String) -> void:
	if phase != Phase.ENDED:
		return
	if _trial_counts[condition] < config.trials_per_condition():
		_show_intro()
	else:
		_show_rating()


func _on_goal_reached() -> void:
	if phase == Phase.TRIAL:
		_end_trial(true)
	elif phase == Phase.PRACTICE:
		_stage.toast("Goal!")
		if not ConditionRig.is_position_control(_rig.condition):
			_rig.respawn()
		get_tree().create_timer(1.0).timeout.connect(_rearm_goal.bind(_stage.level))


func _rearm_goal(level: StudyLevel) -> void:
	if is_instance_valid(level):
		level.reset_goal()


# ---------------------------------------------------------------------------- answers


func _show_rating() -> void:
	_release_stage()
	var screen: RatingScreen = _show_screen(RATING_SCENE) as RatingScreen
	screen.setup("Method %d of %d" % [order_index + 1, condition_order.size()])
	screen.submitted.connect(_on_ratings_submitted)
	_set_phase(Phase.RATING)


func _on_ratings_submitted(ratings: Dictionary) -> void:
	if phase != Phase.RATING:
		return
	if not store.append_rating(current_condition(), order_index, ratings):
		_fatal(store.last_error)
		return
	if order_index + 1 < condition_order.size():
		begin_condition(order_index + 1)
	else:
		_show_final()


func _show_final() -> void:
	_release_stage()
	var screen: FinalScreen = _show_screen(FINAL_SCENE) as FinalScreen
	screen.setup(condition_order)
	screen.submitted.connect(_on_final_submitted)
	_set_phase(Phase.FINAL)


func _on_final_submitted(favourite: PackedStringArray, differences_text: String) -> void:
	if phase != Phase.FINAL:
		return
	if not store.write_final(favourite, differences_text):
		_fatal(store.last_error)
		return
	_finish_session()


func _finish_session() -> void:
	meta["finished"] = StudyFormat.timestamp()
	if not store.replace_participant(meta):
		_fatal(store.last_error)
		return
	_show_message(
		"Thank you!",
		(
			"The session of %s is complete and saved in %s."
			% [store.participant_id, StudyStore.native_path(store.folder())]
		),
		"Back to menu" if not _is_standalone() else "Quit"
	)
	_set_phase(Phase.DONE)
	if quit_when_done:
		get_tree().quit(0)


# ---------------------------------------------------------------------------- helpers


func _load_level(scene: PackedScene, condition: String) -> bool:
	_rig.release()
	var level: StudyLevel = _stage.show_level(scene) if scene != null else null
	if level == null:
		_fatal("the level could not be loaded")
		return false
	level.goal_reached.connect(_on_goal_reached)
	var settings: Dictionary = config.condition(condition)
	_rig.piloted = autopilot
	_rig.pointer = _stage.pointer_in_level
	if not _rig.setup(level, condition, settings):
		_fatal("the haptics server refused the settings of the condition '%s'" % condition)
		return false
	if autopilot:
		_pilot = StudyPilot.new(level.get_autopilot_path(), config.autopilot_speed())
	return true


func _maze_scene() -> PackedScene:
	if _maze == null:
		_maze = load(config.maze_level()) as PackedScene
	return _maze


func _use_stage() -> void:
	if _stage != null and _screen == _stage:
		return
	_stage = _show_screen(STAGE_SCENE) as StudyStage
	_stage.start_pressed.connect(_on_stage_start_pressed)
	_stage.next_level_pressed.connect(_on_next_level_pressed)
	_stage.next_method_pressed.connect(_on_next_method_pressed)
	_stage.ready_pressed.connect(_on_ready_pressed)


func _release_stage() -> void:
	_rig.release()
	if _stage != null:
		_stage.clear_level()


func _show_screen(scene: PackedScene) -> Control:
	if _screen != null:
		if _screen == _stage:
			_release_stage()
			_stage = null
		remove_child(_screen)
		_screen.queue_free()
	_screen = scene.instantiate() as Control
	add_child(_screen)
	return _screen


func _show_message(heading: String, body: String, button: String, is_error: bool = false) -> void:
	var screen: MessageScreen = _show_screen(MESSAGE_SCENE) as MessageScreen
	screen.show_message(heading, body, button, is_error)
	screen.closed.connect(_leave)


# A write failed: the session stops; what was written before is safe.
func _fatal(error: String) -> void:
	push_error("Maze study stopped: " + error)
	var who: String = store.participant_id if store != null else "the participant"
	_show_message(
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
	_set_phase(Phase.STOPPED)


func _set_phase(value: Phase) -> void:
	phase = value
	phase_changed.emit(value)


func _leave() -> void:
	if _is_standalone():
		get_tree().quit(0)
	else:
		closed.emit()


func _is_standalone() -> bool:
	return is_inside_tree() and get_tree().current_scene == self


# Why the study cannot run here, or "".
func _refusal() -> String:
	var lines: PackedStringArray = PackedStringArray()
	for error: String in config.errors:
		lines.append("Study settings: " + error)
	if not StudyStore.is_available():
		lines.append(
			(
				"The haptics extension (DurableFile) is not loaded, so study data cannot be "
				+ "saved safely. Build it with 'make build' and restart."
			)
		)
	elif not Haptics.is_running():
		lines.append("The haptic device is not running: check the device in Settings.")
	return "\n".join(lines)


func _load_config() -> StudyConfig:
	var loaded: StudyConfig = StudyConfig.load_default()
	if not config_path.is_empty():
		loaded.merge_file(config_path)
	if not study_root.is_empty():
		loaded.merge({"study_root": study_root}, "--study-root")
	var root: String = loaded.study_root()
	loaded.merge_file(root.path_join(StudyConfig.ROOT_FILE), true)
	if loaded.study_root() != root:
		loaded.errors.append(
			"%s: 'study_root' cannot be changed from inside the study folder" % root
		)
	return loaded


func _apply_options(options: Dictionary) -> void:
	var trials: int = options.get("trials_per_condition", config.trials_per_condition())
	var values: Dictionary = {
		"trials_per_condition": trials,
		"counterbalancing": str(options.get("counterbalancing", config.counterbalancing())),
		"conditions":
		{
			"constraint":
			{
				"update":
				str(options.get("constraint_update", config.condition("constraint")["update"]))
			}
		},
	}
	config.merge(values, "start screen")


# [text, where it came from]
func _consent() -> PackedStringArray:
	var own: String = config.study_root().path_join("consent.txt")
	for path: String in [own, DEFAULT_CONSENT_PATH]:
		if FileAccess.file_exists(path):
			return PackedStringArray([FileAccess.get_file_as_string(path), path])
	return PackedStringArray(["(No consent text: add %s.)" % own, own])


func _read_command_line() -> void:
	for arg: String in OS.get_cmdline_user_args():
		var value: String = arg.get_slice("=", 1) if arg.contains("=") else ""
		if arg.begins_with("--study-root="):
			study_root = value
		elif arg.begins_with("--study-config="):
			config_path = value
		elif arg.begins_with("--scripted-participant="):
			scripted_participant = value
		elif arg == "--resume":
			scripted_resume = true
		elif arg.begins_with("--hold="):
			scripted_hold_s = value.to_float()
		elif arg == "--quit-when-done":
			quit_when_done = true


static func _app_version() -> String:
	var version: String = str(ProjectSettings.get_setting("application/config/version", ""))
	return version if not version.is_empty() else "dev"
