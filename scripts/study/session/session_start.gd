class_name SessionStart
extends Node
## What the start screen's two buttons do. Start: a new participant gets a folder and a
## participant.json (refused when the id already has data), a condition order and the
## practice. Resume: the participant's folder is scanned ([ParticipantState]) and the
## session continues at its next step (refused, with every problem listed, while anything
## is corrupt). Either way the researcher's options of the start screen are applied first.

@onready var _runner: StudyRunner = get_parent() as StudyRunner


## Starts participant [param id] with the [param demographics] entered.
func start(id: String, demographics: Dictionary, options: Dictionary) -> void:
	var screen: StartScreen = _runner.get_screen() as StartScreen
	var config: StudyConfig = _runner.config
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
	var meta: Dictionary = {
		"format_version": StudyFormat.format_version,
		"participant_id": id,
		"demographics": demographics,
		"seed": order_seed,
		"condition_order": Array(order),
		"counterbalancing": mode,
		"app_version": StudyLaunch.app_version(),
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
	_runner.meta = meta
	_runner.store = candidate
	_runner.condition_order = order
	for condition: String in StudyFormat.conditions:
		_runner.trial_counts[condition] = 0
		_runner.next_index[condition] = 0
	_runner.start_practice()


## Resumes participant [param id] where the session stopped.
func resume(id: String, options: Dictionary) -> void:
	var screen: StartScreen = _runner.get_screen() as StartScreen
	var root: String = _runner.config.study_root()
	_apply_options(options)
	var state: ParticipantState = ParticipantState.scan(root, id)
	_runner.report = state.report_lines()
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
		screen.show_problem("There is no data for %s in %s: nothing to resume." % [id, root])
		return
	for note: String in state.notes:
		print("Maze study: resume %s: %s" % [id, note])
	_runner.store = StudyStore.new(root, id)
	_runner.meta = state.meta
	_runner.condition_order = state.condition_order
	_runner.trial_counts = state.trial_counts
	_runner.next_index = state.next_index
	_continue(state.next_step(_runner.config.trials_per_condition()), id)


func _continue(next: Dictionary, id: String) -> void:
	var step: ParticipantState.Step = next["step"]
	_runner.order_index = next["order_index"]
	match step:
		ParticipantState.Step.PRACTICE:
			_runner.start_practice()
		ParticipantState.Step.TRIALS:
			if _runner.config.practice_on_resume():
				_runner.start_practice()
			else:
				_runner.begin_condition(_runner.order_index)
		ParticipantState.Step.RATING:
			_runner.answers.show_rating()
		ParticipantState.Step.FINAL:
			_runner.answers.show_final()
		ParticipantState.Step.FINISH:
			_runner.answers.finish_session()
		ParticipantState.Step.DONE:
			var screen: StartScreen = _runner.get_screen() as StartScreen
			screen.show_problem("%s has finished the study: there is nothing to resume." % id)


func _apply_options(options: Dictionary) -> void:
	var config: StudyConfig = _runner.config
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
