class_name StartScreen
extends Control
## The study's first screen, for the researcher and the participant: participant id,
## demographics (the value lists of the study schema), the consent text (editable by the
## researcher, see [StudyLaunch]), and the researcher's options for this session. Start
## begins a new participant; Resume continues one whose session was interrupted. The screen
## checks its own fields; the runner checks the data folder and answers with
## [method show_problem] when it refuses.

## Start a new participant.
signal start_requested(participant_id: String, demographics: Dictionary, options: Dictionary)
## Resume the participant [param participant_id].
signal resume_requested(participant_id: String, options: Dictionary)
## Leave the study.
signal back_requested

## What the researcher's option buttons show for each value.
const OPTION_LABELS: Dictionary = {
	"random": "Random (recorded seed)",
	"latin_square": "Latin square (Williams)",
	"servo": "1 kHz (servo thread)",
	"frame": "50 Hz (physics frames, as the paper)",
}
## The setting behind the constraint proxy update option.
const PROXY_UPDATE_SETTING: String = "conditions.constraint.update"

## One option button per demographic field.
var demographic_options: Dictionary[String, OptionButton] = {}

var _order_modes: PackedStringArray = StudyFormat.counterbalancing_modes
var _proxy_updates: PackedStringArray = StudyConfig.choices(PROXY_UPDATE_SETTING)

@onready var id_edit: LineEdit = %IdEdit
@onready var consent_check: CheckBox = %ConsentCheck
## Counterbalancing option.
@onready var order_option: OptionButton = %OrderOption
## Constraint proxy update option.
@onready var proxy_option: OptionButton = %ProxyOption
## Trials per condition.
@onready var trials_spin: SpinBox = %TrialsSpin
@onready var start_button: Button = %StartButton
@onready var resume_button: Button = %ResumeButton
@onready var back_button: Button = %BackButton
## Where refusals and problems are shown.
@onready var problem_label: Label = %Problem
@onready var _consent_text: Label = %ConsentText
@onready var _consent_hint: Label = %ConsentHint
@onready var _fields: GridContainer = %Fields
@onready var _data_label: Label = %DataLabel


func _ready() -> void:
	StudyTheme.apply(self)
	for key: String in StudyFormat.demographic_keys():
		_add_demographic(key)
	_fill(order_option, _order_modes)
	_fill(proxy_option, _proxy_updates)
	start_button.pressed.connect(_on_start_pressed)
	resume_button.pressed.connect(_on_resume_pressed)
	back_button.pressed.connect(back_requested.emit)
	id_edit.text_submitted.connect(_on_id_submitted)
	show_problem("")
	UiFocus.grab_later(id_edit)


## Shows the consent text and where the researcher edits it.
func set_consent_text(text: String, source: String) -> void:
	_consent_text.text = text.strip_edges()
	_consent_hint.text = (
		"Shown from %s (your approved text goes in consent.txt in the study folder)" % source
		if source.begins_with("res://")
		else "Shown from %s" % source
	)
	# The line is cut to the card's width at 1280x720 and below: the whole of it on hover.
	_consent_hint.tooltip_text = _consent_hint.text
	_consent_hint.mouse_filter = Control.MOUSE_FILTER_PASS


## Shows the study folder; a long path wraps after a folder separator, never inside a name
## (a zero-width space after each one is where the line may break).
func set_data_folder(path: String) -> void:
	_data_label.text = "Data: %s" % path.replace("/", "/\u200b")


## Presets the researcher's options.
func set_options(counterbalancing: String, proxy_update: String, trials: int) -> void:
	order_option.select(maxi(0, _order_modes.find(counterbalancing)))
	proxy_option.select(maxi(0, _proxy_updates.find(proxy_update)))
	trials_spin.value = trials


## The researcher's options as chosen.
func get_options() -> Dictionary:
	return {
		"counterbalancing": _order_modes[maxi(0, order_option.selected)],
		"constraint_update": _proxy_updates[maxi(0, proxy_option.selected)],
		"trials_per_condition": int(trials_spin.value),
	}


## Selects [param value] for the demographic [param key] (false when not allowed).
func set_demographic(key: String, value: String) -> bool:
	var index: int = StudyFormat.demographic_values(key).find(value)
	if index < 0:
		return false
	demographic_options[key].select(index + 1)
	return true


## The demographics chosen so far (fields still on "Choose…" are missing).
func get_demographics() -> Dictionary:
	var out: Dictionary = {}
	for key: String in demographic_options:
		var selected: int = demographic_options[key].selected
		if selected > 0:
			out[key] = StudyFormat.demographic_values(key)[selected - 1]
	return out


## Shows [param text] as a problem (empty hides it).
func show_problem(text: String) -> void:
	problem_label.text = text
	problem_label.visible = not text.is_empty()


static func _fill(option: OptionButton, values: PackedStringArray) -> void:
	option.clear()
	for value: String in values:
		option.add_item(str(OPTION_LABELS.get(value, value)))


func _add_demographic(key: String) -> void:
	var label: Label = Label.new()
	label.theme_type_variation = &"FieldLabel"
	label.text = StudyFormat.demographic_title(key)
	_fields.add_child(label)
	var option: OptionButton = OptionButton.new()
	option.name = key.to_pascal_case() + "Option"
	option.custom_minimum_size = Vector2(260.0, 0.0)
	option.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	option.add_item("Choose…")
	for value: String in StudyFormat.demographic_values(key):
		option.add_item(StudyFormat.value_label(value))
	option.select(0)
	_fields.add_child(option)
	demographic_options[key] = option


func _checked_id() -> String:
	var id: String = id_edit.text.strip_edges()
	if id.is_empty():
		show_problem("Enter a participant ID (letters, digits, - and _; e.g. P07).")
		return ""
	if not StudyFormat.is_valid_id(id):
		show_problem(
			(
				(
					"'%s' is not a valid participant ID: use letters, digits, - and _, "
					+ "starting with a letter or digit."
				)
				% id
			)
		)
		return ""
	return id


func _on_start_pressed() -> void:
	var id: String = _checked_id()
	if id.is_empty():
		return
	var demographics: Dictionary = get_demographics()
	var missing: PackedStringArray = PackedStringArray()
	for key: String in StudyFormat.demographic_keys():
		if not demographics.has(key):
			missing.append(StudyFormat.demographic_title(key).to_lower())
	if not missing.is_empty():
		show_problem("Please choose: %s." % ", ".join(missing))
		return
	if not consent_check.button_pressed:
		show_problem("The participant's consent is needed before the study starts.")
		return
	show_problem("")
	start_requested.emit(id, demographics, get_options())


func _on_resume_pressed() -> void:
	var id: String = _checked_id()
	if id.is_empty():
		return
	show_problem("")
	resume_requested.emit(id, get_options())


func _on_id_submitted(_text: String) -> void:
	demographic_options["age_band"].grab_focus()
