class_name SessionStart
extends Node
## What the start screen's two buttons do. Start: a new participant gets a folder and a
## participant.json (refused when the id already has data), a condition order and the
## practice. Resume: the participant's folder is scanned ([ParticipantState]) and the
## session continues at its next step (refused, with every problem listed, while anything
## is corrupt). Either way the researcher's options of the start screen are applied first.
## The session ([StudySession]) gets the participant; the signals say where it goes on.

## The session of a participant is set up: it goes on at [param step] (a new participant:
## the practice).
signal started(step: ParticipantState.Step)
## Nothing was started: [param problem] says why (for the start screen).
signal refused(problem: String)

var _session: StudySession = null


## Hands the step the session it sets up.
func setup(session: StudySession) -> void:
	_session = session


## Starts participant [param id] with the [param demographics] entered.
func start(id: String, demographics: Dictionary, options: Dictionary) -> void:
	var config: StudyConfig = _session.config
	_apply_options(options)
	var candidate: StudyStore = StudyStore.new(config.study_root(), id)
	if candidate.has_data():
		refused.emit(
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
		# What a reader needs to recompute wall_collisions from the telemetry (FORMAT.md).
		"contact_gap_s": config.number("contact_gap_s"),
	}
	if not candidate.create(meta):
		refused.emit("Could not create the participant's data: %s" % candidate.last_error)
		push_error("Maze study: " + candidate.last_error)
		return
	_session.meta = meta
	_session.store = candidate
	_session.condition_order = order
	for condition: String in StudyFormat.conditions:
		_session.trial_counts[condition] = 0
		_session.next_index[condition] = 0
	started.emit(ParticipantState.Step.PRACTICE)


## Resumes participant [param id] where the session stopped.
func resume(id: String, options: Dictionary) -> void:
	var root: String = _session.config.study_root()
	_apply_options(options)
	var state: ParticipantState = ParticipantState.scan(root, id)
	_session.report = state.report_lines()
	if not state.problems.is_empty():
		for problem: String in state.problems:
			push_error("Maze study data problem: " + problem)
		refused.emit(
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
		refused.emit("There is no data for %s in %s: nothing to resume." % [id, root])
		return
	for note: String in state.notes:
		print("Maze study: resume %s: %s" % [id, note])
	_session.store = StudyStore.new(root, id)
	_session.meta = state.meta
	_session.condition_order = state.condition_order
	_session.trial_counts = state.trial_counts
	_session.next_index = state.next_index
	var next: Dictionary = state.next_step(_session.config.trials_per_condition())
	var step: ParticipantState.Step = next["step"]
	_session.order_index = next["order_index"]
	if step == ParticipantState.Step.DONE:
		refused.emit("%s has finished the study: there is nothing to resume." % id)
	elif step == ParticipantState.Step.TRIALS and _session.config.practice_on_resume():
		started.emit(ParticipantState.Step.PRACTICE)
	else:
		started.emit(step)


func _apply_options(options: Dictionary) -> void:
	var config: StudyConfig = _session.config
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
