class_name AnswerFlow
extends Node
## The participant's answers: the six ratings after each condition's trials, then the
## differences felt and the favourite, then the end of the session (participant.json gets
## its [code]finished[/code] time). Each answer is written before the next screen shows.

const RATING_SCENE: PackedScene = preload("res://scenes/study/rating_screen.tscn")
const FINAL_SCENE: PackedScene = preload("res://scenes/study/final_screen.tscn")

@onready var _runner: StudyRunner = get_parent() as StudyRunner


## Asks for the six ratings of the current condition.
func show_rating() -> void:
	_runner.release_stage()
	var screen: RatingScreen = _runner.show_screen(RATING_SCENE) as RatingScreen
	screen.setup(_runner.method_heading())
	screen.submitted.connect(_on_ratings_submitted)
	_runner.phase = StudyRunner.Phase.RATING


## Asks for the differences felt and the favourite.
func show_final() -> void:
	_runner.release_stage()
	var screen: FinalScreen = _runner.show_screen(FINAL_SCENE) as FinalScreen
	screen.setup(_runner.condition_order)
	screen.submitted.connect(_on_final_submitted)
	_runner.phase = StudyRunner.Phase.FINAL


## Records the end of the session and thanks the participant.
func finish_session() -> void:
	var store: StudyStore = _runner.store
	_runner.meta["finished"] = StudyFormat.timestamp()
	if not store.replace_participant(_runner.meta):
		_runner.fatal(store.last_error)
		return
	_runner.show_message(
		"Thank you!",
		(
			"The session of %s is complete and saved in %s."
			% [store.participant_id, StudyStore.native_path(store.folder())]
		),
		"Back to menu" if not _runner.is_standalone() else "Quit"
	)
	_runner.phase = StudyRunner.Phase.DONE
	if _runner.quit_when_done:
		CleanExit.quit(0)


func _on_ratings_submitted(ratings: Dictionary) -> void:
	if _runner.phase != StudyRunner.Phase.RATING:
		return
	var order_index: int = _runner.order_index
	if not _runner.store.append_rating(_runner.current_condition(), order_index, ratings):
		_runner.fatal(_runner.store.last_error)
		return
	if order_index + 1 < _runner.condition_order.size():
		_runner.begin_condition(order_index + 1)
	else:
		show_final()


func _on_final_submitted(favourite: PackedStringArray, differences_text: String) -> void:
	if _runner.phase != StudyRunner.Phase.FINAL:
		return
	if not _runner.store.write_final(favourite, differences_text):
		_runner.fatal(_runner.store.last_error)
		return
	finish_session()
