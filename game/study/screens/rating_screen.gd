class_name RatingScreen
extends Control
## After each condition: the six criteria of the paper, each rated on the format's scale
## (1–10) with the paper's wording. Submit is enabled once all six have a value. Keyboard:
## the arrow keys move between the numbers, Enter/Space picks one; the mouse clicks them.

## The participant submitted; [param ratings] maps each of
## [member StudyFormat.criteria] to its rating.
signal submitted(ratings: Dictionary)

## The number buttons: criterion → one button per rating, lowest first.
var buttons: Dictionary[String, Array] = {}

var _groups: Dictionary[String, ButtonGroup] = {}

## The heading ("Method 2 of 3").
@onready var heading: Label = %Heading
@onready var submit_button: Button = %SubmitButton
@onready var _grid: GridContainer = %Grid
@onready var _hint: Label = %Hint


func _ready() -> void:
	StudyTheme.apply(self)
	for criterion: String in StudyFormat.criteria:
		_add_row(criterion)
	submit_button.pressed.connect(_on_submit_pressed)
	_refresh()
	var first: Button = buttons[StudyFormat.criteria[0]][0]
	UiFocus.grab_later(first)


## Shows [param text] as the heading and clears any earlier answers.
func setup(text: String) -> void:
	heading.text = text
	for criterion: String in buttons:
		for button: Button in buttons[criterion]:
			button.set_pressed_no_signal(false)
	_refresh()


## Picks [param value] (clamped to the scale) for [param criterion], as a click would.
func set_rating(criterion: String, value: int) -> void:
	var lowest: int = StudyFormat.rating_min
	var button: Button = buttons[criterion][clampi(value, lowest, StudyFormat.rating_max) - lowest]
	button.button_pressed = true
	_refresh()


## The values picked so far: criterion → rating (missing when not yet rated).
func get_ratings() -> Dictionary:
	var out: Dictionary = {}
	for criterion: String in _groups:
		var pressed: BaseButton = _groups[criterion].get_pressed_button()
		if pressed != null:
			var value: int = pressed.get_meta(&"value")
			out[criterion] = value
	return out


## Whether all six criteria have a value.
func is_complete() -> bool:
	return get_ratings().size() == StudyFormat.criteria.size()


func _add_row(criterion: String) -> void:
	var criterion_title: String = StudyFormat.criterion_title(criterion)
	var label_box: VBoxContainer = VBoxContainer.new()
	label_box.add_theme_constant_override(&"separation", 0)
	label_box.custom_minimum_size = Vector2(430.0, 0.0)
	var title: Label = Label.new()
	title.theme_type_variation = &"CriterionLabel"
	title.text = criterion_title
	var question: Label = Label.new()
	question.theme_type_variation = &"QuestionLabel"
	question.text = StudyFormat.criterion_question(criterion)
	label_box.add_child(title)
	label_box.add_child(question)
	_grid.add_child(label_box)
	var row: HBoxContainer = HBoxContainer.new()
	row.add_theme_constant_override(&"separation", 6)
	row.alignment = BoxContainer.ALIGNMENT_CENTER
	var group: ButtonGroup = ButtonGroup.new()
	_groups[criterion] = group
	var row_buttons: Array[Button] = []
	for value: int in range(StudyFormat.rating_min, StudyFormat.rating_max + 1):
		var button: Button = Button.new()
		button.theme_type_variation = &"RatingButton"
		button.text = str(value)
		button.toggle_mode = true
		button.button_group = group
		button.custom_minimum_size = Vector2(50.0, 46.0)
		button.set_meta(&"value", value)
		button.name = "%s_%d" % [criterion, value]
		button.tooltip_text = "%s: %d" % [criterion_title, value]
		button.toggled.connect(_on_toggled)
		row.add_child(button)
		row_buttons.append(button)
	buttons[criterion] = row_buttons
	_grid.add_child(row)


func _refresh() -> void:
	var missing: int = StudyFormat.criteria.size() - get_ratings().size()
	submit_button.disabled = missing > 0
	if missing > 0:
		_hint.text = "%d still to rate" % missing if missing > 1 else "1 still to rate"
	else:
		_hint.text = "All rated: submit when you are happy with your answers"


func _on_toggled(_pressed: bool) -> void:
	_refresh()


func _on_submit_pressed() -> void:
	if is_complete():
		submitted.emit(get_ratings())
