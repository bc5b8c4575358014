class_name FinalScreen
extends Control
## The end of the session: free text on the differences the participant felt between the
## methods, and their favourite (one, several, or none). Methods are named by the order
## they were presented in ("Method 1" …), never by condition.

## The participant finished; [param favourite] lists conditions (presentation order),
## [param differences_text] is the free text.
signal submitted(favourite: PackedStringArray, differences_text: String)

var _order: PackedStringArray = StudyFormat.conditions.duplicate()
var _checks: Array[CheckBox] = []

@onready var text_edit: TextEdit = %Differences
@onready var submit_button: Button = %SubmitButton
@onready var _choices: VBoxContainer = %Choices


func _ready() -> void:
	StudyTheme.apply(self)
	submit_button.pressed.connect(_on_submit_pressed)
	setup(_order)
	UiFocus.grab_later(text_edit)


## Names one check box per condition of [param order] (the presentation order).
func setup(order: PackedStringArray) -> void:
	_order = order
	for check: CheckBox in _checks:
		check.queue_free()
	_checks.clear()
	var ordinals: PackedStringArray = ["first", "second", "third"]
	for i: int in order.size():
		var check: CheckBox = CheckBox.new()
		check.text = "Method %d  (the %s one you used)" % [i + 1, ordinals[mini(i, 2)]]
		_choices.add_child(check)
		_checks.append(check)


## Ticks the methods at [param indices] (presentation order) and unticks the others.
func set_favourite(indices: PackedInt32Array) -> void:
	for i: int in _checks.size():
		_checks[i].button_pressed = i in indices


## The ticked methods as conditions, in presentation order.
func get_favourite() -> PackedStringArray:
	var out: PackedStringArray = PackedStringArray()
	for i: int in _checks.size():
		if _checks[i].button_pressed:
			out.append(_order[i])
	return out


func _on_submit_pressed() -> void:
	submitted.emit(get_favourite(), text_edit.text.strip_edges())
