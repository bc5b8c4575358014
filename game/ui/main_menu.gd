class_name MainMenu
extends Control
## The title screen: Play, the 3D room and the drive (one row), Haptic Battle Pong, Maze
## study, Settings, Quit.
## Navigable with keyboard or gamepad (the first button takes focus) and clickable with the
## mouse. It only emits signals; the main scene decides what each one does.

signal play_requested
signal room_3d_requested
signal drive_requested
signal pong_requested
signal maze_requested
signal settings_requested
signal quit_requested

var _status_timer: float = 0.0

@onready var play_button: Button = %PlayButton
@onready var room_3d_button: Button = %Room3DButton
@onready var drive_button: Button = %DriveButton
@onready var pong_button: Button = %PongButton
@onready var maze_button: Button = %MazeButton
@onready var settings_button: Button = %SettingsButton
@onready var quit_button: Button = %QuitButton
@onready var _status: Label = %Status


func _ready() -> void:
	play_button.pressed.connect(play_requested.emit)
	room_3d_button.pressed.connect(room_3d_requested.emit)
	drive_button.pressed.connect(drive_requested.emit)
	pong_button.pressed.connect(pong_requested.emit)
	maze_button.pressed.connect(maze_requested.emit)
	settings_button.pressed.connect(settings_requested.emit)
	quit_button.pressed.connect(quit_requested.emit)
	_status.text = device_status_text()
	# One name for the game: the project's, which the window title and exports carry too.
	(%Title as Label).text = ProjectSettings.get_setting("application/config/name")
	UiFocus.grab_later(play_button)


func _process(delta: float) -> void:
	_status_timer -= delta
	if _status_timer <= 0.0:
		_status_timer = 0.5
		_status.text = device_status_text()


## One line describing the haptic device: its name and servo rate, or why there is none.
static func device_status_text() -> String:
	if not Haptics.is_available():
		return "Haptics extension not loaded: playing without force feedback"
	var device_name: String = Haptics.device.get_name()
	if device_name.is_empty():
		return "No haptic device open"
	var rate: float = Haptics.servo.get_rate_hz()
	if rate > 0.0:
		return "%s  ·  servo %d Hz" % [device_name, roundi(rate)]
	return device_name
