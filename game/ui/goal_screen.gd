class_name GoalScreen
extends CanvasLayer
## Shown when the player reaches the goal: the time taken and the items collected, with
## Play again and Menu. Showing it pauses the tree; it processes while paused.

signal play_again_requested
signal menu_requested

@onready var play_again_button: Button = %PlayAgainButton
@onready var menu_button: Button = %MenuButton
@onready var _time_value: Label = %TimeValue
@onready var _items_value: Label = %ItemsValue


func _ready() -> void:
	process_mode = PROCESS_MODE_ALWAYS
	visible = false
	play_again_button.pressed.connect(_on_play_again_pressed)
	menu_button.pressed.connect(_on_menu_pressed)


## Shows the result and pauses the tree. [param total] below 0 means unknown.
func show_result(seconds: float, collected: int, total: int) -> void:
	_time_value.text = format_time(seconds)
	_items_value.text = format_items(collected, total)
	visible = true
	get_tree().paused = true
	UiFocus.grab_later(play_again_button)


## The time text shown, e.g. [code]01:23.4[/code].
func get_time_text() -> String:
	return _time_value.text


## The items text shown, e.g. [code]3 / 5[/code].
func get_items_text() -> String:
	return _items_value.text


## Formats [param seconds] as minutes:seconds.tenths.
static func format_time(seconds: float) -> String:
	var tenths: int = floori(maxf(seconds, 0.0) * 10.0)
	var whole_seconds: int = floori(tenths / 10.0)
	return "%02d:%02d.%d" % [floori(whole_seconds / 60.0), whole_seconds % 60, tenths % 10]


## Formats an item count; [param total] below 0 means unknown.
static func format_items(collected: int, total: int) -> String:
	if total < 0:
		return str(collected)
	return "%d / %d" % [collected, total]


func _on_play_again_pressed() -> void:
	visible = false
	get_tree().paused = false
	play_again_requested.emit()


func _on_menu_pressed() -> void:
	visible = false
	get_tree().paused = false
	menu_requested.emit()
