class_name MessageScreen
extends Control
## A full-screen message with one button: the thank-you at the end of a session, or why the
## study cannot go on (the extension is missing, data could not be saved).

## The button was pressed.
signal closed

@onready var heading: Label = %Heading
## The message (scrolls when long).
@onready var body: Label = %Body
@onready var button: Button = %Button
@onready var _scroll: ScrollContainer = %Scroll


func _ready() -> void:
	StudyTheme.apply(self)
	button.pressed.connect(closed.emit)
	UiFocus.grab_later(button)


## Shows [param p_heading] and [param p_body]; [param is_error] colours the text as a warning.
func show_message(
	p_heading: String, p_body: String, button_text: String = "Back to menu", is_error: bool = false
) -> void:
	heading.text = p_heading
	body.text = p_body
	body.theme_type_variation = &"ErrorLabel" if is_error else &"QuestionLabel"
	button.text = button_text
	UiFocus.grab_later(button)
	_fit.call_deferred()


# The text area grows with the message up to about two thirds of the screen, then scrolls.
func _fit() -> void:
	var wanted: float = body.get_combined_minimum_size().y
	_scroll.custom_minimum_size.y = clampf(wanted, 60.0, size.y * 0.6)
