class_name StudySession
extends RefCounted
## One participant's session as the study's steps share it: the settings, where the flow
## is, the participant's writer and record, the condition order and how far each condition
## has come. The [StudyRunner] makes it and hands it to each step; a step changes it and
## signals what should follow.

## The flow moved to [param new_phase].
signal phase_changed(new_phase: Phase)

## Where the flow is.
enum Phase { START, PRACTICE, INTRO, CENTRING, TRIAL, ENDED, RATING, FINAL, DONE, STOPPED }

## The merged settings.
var config: StudyConfig = null
## Where the flow is; setting it emits [signal phase_changed].
var phase: Phase = Phase.START:
	set(value):
		phase = value
		phase_changed.emit(value)
## The participant's writer (null before a session starts).
var store: StudyStore = null
## participant.json of the session.
var meta: Dictionary = {}
## The participant's condition order.
var condition_order: PackedStringArray = PackedStringArray()
## Index into [member condition_order] of the condition being run or rated.
var order_index: int = 0
## Trial records written so far, per condition.
var trial_counts: Dictionary[String, int] = {}
## Per condition, the next unused trial index.
var next_index: Dictionary[String, int] = {}
## The last resume report (problems and notes).
var report: PackedStringArray = PackedStringArray()
## The measures of the last trial recorded.
var last_result: TrialResult = null


func _init(p_config: StudyConfig = null) -> void:
	config = p_config


## The condition being run or rated.
func current_condition() -> String:
	return condition_order[order_index] if order_index < condition_order.size() else ""


## What participants call the current condition ("Method 2 of 3"), never its id.
func method_heading() -> String:
	return "Method %d of %d" % [order_index + 1, condition_order.size()]
