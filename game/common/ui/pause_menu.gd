class_name PauseMenu
extends CanvasLayer
## The pause menu: the [code]pause[/code] action opens it (pausing the tree) and closes it
## again; Resume, Settings (shown over the game) and Quit to menu. It processes while the
## tree is paused ([constant Node.PROCESS_MODE_ALWAYS]); the game below it is pausable.

## The player chose Quit to menu (the tree is unpaused first).
signal quit_requested

## The settings screen shown by the Settings button.
const SETTINGS_SCENE: PackedScene = preload("res://game/common/ui/settings_screen.tscn")

## Whether the pause action opens the menu (off once the goal screen shows).
var enabled: bool = true

var _settings_screen: SettingsScreen = null

@onready var resume_button: Button = %ResumeButton
@onready var settings_button: Button = %SettingsButton
@onready var quit_button: Button = %QuitButton
@onready var _root: Control = %Root
@onready var _panel: Control = %Center


func _ready() -> void:
	process_mode = PROCESS_MODE_ALWAYS
	visible = false
	resume_button.pressed.connect(close)
	settings_button.pressed.connect(open_settings)
	quit_button.pressed.connect(_on_quit_pressed)


func _unhandled_input(event: InputEvent) -> void:
	if not event.is_action_pressed(&"pause"):
		return
	if is_open():
		get_viewport().set_input_as_handled()
		if _settings_screen != null:
			_settings_screen.close()
		else:
			close()
	elif enabled:
		get_viewport().set_input_as_handled()
		open()


## Whether the menu shows (and so the tree is paused).
func is_open() -> bool:
	return visible


## Shows the menu and pauses the tree.
func open() -> void:
	visible = true
	_panel.visible = true
	get_tree().paused = true
	UiFocus.grab_later(resume_button)


## Hides the menu (and any settings shown from it) and resumes the game.
func close() -> void:
	_close_settings()
	visible = false
	get_tree().paused = false


## Shows the settings screen over the game; the menu comes back when it closes.
func open_settings() -> void:
	if _settings_screen != null:
		return
	_settings_screen = SETTINGS_SCENE.instantiate() as SettingsScreen
	_settings_screen.dim_background = true
	_settings_screen.closed.connect(_on_settings_closed)
	_panel.visible = false
	_root.add_child(_settings_screen)


## The settings screen while it shows, else null.
func get_settings_screen() -> SettingsScreen:
	return _settings_screen


func _close_settings() -> void:
	if _settings_screen == null:
		return
	_root.remove_child(_settings_screen)
	_settings_screen.queue_free()
	_settings_screen = null
	_panel.visible = true


func _on_settings_closed() -> void:
	_close_settings()
	UiFocus.grab_later(settings_button)


func _on_quit_pressed() -> void:
	close()
	quit_requested.emit()
