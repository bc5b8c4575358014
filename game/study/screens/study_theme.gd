class_name StudyTheme
extends RefCounted
## The study screens' theme: the project's theme ([constant BASE_PATH]) with the study's
## additions merged in ([constant EXTRA_PATH]: text fields, check boxes, the rating buttons,
## labels for forms). Screens keep the project theme in their scenes and call [method apply]
## when ready, so they look right alone and inside the study.

## The project's theme.
const BASE_PATH: String = "res://assets/ui/theme.tres"
## The study's additions.
const EXTRA_PATH: String = "res://assets/study/study_theme.tres"

static var _merged: Theme = null


## The merged theme (built once).
static func merged() -> Theme:
	if _merged == null:
		var base: Theme = load(BASE_PATH) as Theme
		_merged = base.duplicate() as Theme if base != null else Theme.new()
		var extra: Theme = load(EXTRA_PATH) as Theme
		if extra != null:
			_merged.merge_with(extra)
	return _merged


## Gives [param control] the merged theme.
static func apply(control: Control) -> void:
	control.theme = merged()
