class_name PongWinnerScreen
extends CanvasLayer
## Shown when a player's health reaches 0: who won, the health left, Play again and Menu.
## Showing it pauses the tree; it processes while paused.

signal play_again_requested
signal menu_requested

@onready var play_again_button: Button = %PlayAgainButton
@onready var menu_button: Button = %MenuButton
@onready var _heading: Label = %Heading
@onready var _summary: Label = %Summary


func _ready() -> void:
	process_mode = PROCESS_MODE_ALWAYS
	visible = false
	play_again_button.pressed.connect(_leave.bind(play_again_requested))
	menu_button.pressed.connect(_leave.bind(menu_requested))


## Shows [param winner_name] as the winner with the final [param health] of both players;
## [param pause] pauses the tree (a headless demo keeps running to print its result).
func show_winner(winner_name: String, health: Array[int], pause: bool = true) -> void:
	_heading.text = "%s wins!" % winner_name
	_summary.text = "Health " + " : ".join(health.map(func(h: int) -> String: return str(h)))
	visible = true
	if pause:
		get_tree().paused = true
	UiFocus.grab_later(play_again_button)


func get_heading() -> String:
	return _heading.text


func _leave(request: Signal) -> void:
	visible = false
	get_tree().paused = false
	request.emit()
