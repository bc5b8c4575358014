class_name MazePlaceholder
extends Control
## Placeholder for the maze study (the paper's experiment) until that issue lands: a short
## description and a Back button.

## The player left the screen.
signal closed

## The Back button.
@onready var back_button: Button = %BackButton


func _ready() -> void:
	back_button.pressed.connect(closed.emit)
	UiFocus.grab_later(back_button)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		closed.emit()
