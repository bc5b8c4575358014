class_name AnswerFlow
extends Node
## The participant's answers: the six ratings after each condition's trials, then the
## differences felt and the favourite, then the end of the session (participant.json gets
## its [code]finished[/code] time). Each answer is written before the next screen shows;
## the [StudyRunner] shows the screens and goes on where the signals say.

## The ratings of the condition at [param order_index] are written: the next condition
## ([param order_index] + 1) or, after the last, the final questions follow.
signal rated(order_index: int)
## participant.json has its finished time: the session is complete.
signal finished
## An answer could not be written: the study stops.
signal failed(error: String)

var _session: StudySession = null


## Hands the flow the session it writes into.
func setup(session: StudySession) -> void:
	_session = session


## Asks [param screen] for the six ratings of the current condition.
func ask_ratings(screen: RatingScreen) -> void:
	screen.setup(_session.method_heading())
	screen.submitted.connect(_on_ratings_submitted)
	_session.phase = StudySession.Phase.RATING


## Asks [param screen] for the differences felt and the favourite.
func ask_final(screen: FinalScreen) -> void:
	screen.setup(_session.condition_order)
	screen.submitted.connect(_on_final_submitted)
	_session.phase = StudySession.Phase.FINAL


## Records the end of the session.
func finish_session() -> void:
	var store: StudyStore = _session.store
	_session.meta["finished"] = StudyFormat.timestamp()
	if not store.replace_participant(_session.meta):
		failed.emit(store.last_error)
		return
	finished.emit()


func _on_ratings_submitted(ratings: Dictionary) -> void:
	if _session.phase != StudySession.Phase.RATING:
		return
	var order_index: int = _session.order_index
	if not _session.store.append_rating(_session.current_condition(), order_index, ratings):
		failed.emit(_session.store.last_error)
		return
	rated.emit(order_index)


func _on_final_submitted(favourite: PackedStringArray, differences_text: String) -> void:
	if _session.phase != StudySession.Phase.FINAL:
		return
	if not _session.store.write_final(favourite, differences_text):
		failed.emit(_session.store.last_error)
		return
	finish_session()
