class_name StudyStage
extends Control
## Where a study level is played: the level in its own viewport (own physics world, a
## camera that fits the level's bounds to the screen), a bar on top (what is going on; in
## practice the Next level / Next method / Ready buttons) and a card in the middle for
## instructions, the centring gauge and a Start button. It only shows things and emits
## signals; [StudyRunner] decides what happens.

## The participant pressed the card's button.
signal start_pressed
## Practice: the participant asked for the next demonstration level.
signal next_level_pressed
## Practice: the participant asked for the next condition (the Next method button).
signal next_condition_pressed
## Practice: the participant is ready for the study.
signal ready_pressed

## Margin around the level's bounds, in level pixels.
const MARGIN: float = 24.0


## Where the handle points in the maze (position control, before a trial starts).
class HandMarker:
	extends Node2D

	func _draw() -> void:
		var colour: Color = Color(1.0, 1.0, 1.0, 0.9)
		draw_arc(Vector2.ZERO, 14.0, 0.0, TAU, 32, colour, 2.0, true)
		for direction: Vector2 in [Vector2.RIGHT, Vector2.LEFT, Vector2.UP, Vector2.DOWN]:
			draw_line(direction * 6.0, direction * 22.0, colour, 2.0, true)


## The level shown, or null.
var level: StudyLevel = null

var _toast_left: float = 0.0
var _hand_marker: HandMarker = null

## The top bar's title.
@onready var title_label: Label = %Title
## The top bar's second line.
@onready var info_label: Label = %Info
## Practice: next demonstration level.
@onready var next_level_button: Button = %NextLevelButton
## Practice: next condition.
@onready var next_condition_button: Button = %NextConditionButton
## Practice: ready for the study.
@onready var ready_button: Button = %ReadyButton
## The card's button.
@onready var start_button: Button = %StartButton
## The card's heading.
@onready var card_heading: Label = %CardHeading
## The card's text.
@onready var card_body: Label = %CardBody
## The centring gauge on the card.
@onready var gauge: CentreGauge = %Gauge
@onready var _card: Control = %Card
@onready var _card_centre: Control = %CardCentre
@onready var _view: Control = %View
@onready var _viewport: SubViewport = %Viewport
@onready var _camera: Camera2D = %Camera
@onready var _toast: Label = %Toast


func _ready() -> void:
	start_button.pressed.connect(start_pressed.emit)
	next_level_button.pressed.connect(next_level_pressed.emit)
	next_condition_button.pressed.connect(next_condition_pressed.emit)
	ready_button.pressed.connect(ready_pressed.emit)
	_viewport.size_changed.connect(fit_camera)
	show_practice_controls(false)
	hide_card()
	_toast.hide()


func _process(delta: float) -> void:
	if _toast.visible:
		_toast_left -= delta
		if _toast_left <= 0.0:
			_toast.hide()


## Shows a new instance of [param scene] (a [StudyLevel]); the previous level is freed.
## Returns the level, or null (and an error) when the scene's root is not a [StudyLevel].
func show_level(scene: PackedScene) -> StudyLevel:
	clear_level()
	var node: Node = scene.instantiate()
	level = node as StudyLevel
	if level == null:
		push_error("Study level %s is not a StudyLevel." % scene.resource_path)
		node.free()
		return null
	_viewport.add_child(level)
	_hand_marker = HandMarker.new()
	_hand_marker.z_index = 50
	_hand_marker.hide()
	level.add_child(_hand_marker)
	fit_camera()
	return level


## Frees the level shown.
func clear_level() -> void:
	if is_instance_valid(level):
		_viewport.remove_child(level)
		level.queue_free()
	level = null
	_hand_marker = null


## The mouse pointer in the level's coordinates (maze units).
func pointer_in_level() -> Vector2:
	var local: Vector2 = _view.get_local_mouse_position()
	return _viewport.get_canvas_transform().affine_inverse() * local


## Shows the handle's point in the maze at [param point] (maze units), or hides it.
func show_hand(point: Vector2, shown: bool) -> void:
	if _hand_marker == null:
		return
	_hand_marker.visible = shown
	_hand_marker.position = point


## Zooms and centres the camera on the level's bounds.
func fit_camera() -> void:
	if level == null or not is_instance_valid(_camera):
		return
	var area: Rect2 = level.get_bounds().grow(MARGIN)
	var view: Vector2 = Vector2(_viewport.size)
	if not area.has_area() or view.x <= 0.0 or view.y <= 0.0:
		return
	var zoom: float = minf(view.x / area.size.x, view.y / area.size.y)
	_camera.zoom = Vector2(zoom, zoom)
	_camera.position = area.get_center()
	_camera.reset_smoothing()


## Sets the top bar's two lines.
func set_status(title: String, info: String) -> void:
	title_label.text = title
	info_label.text = info


## Shows or hides the practice buttons.
func show_practice_controls(shown: bool) -> void:
	next_level_button.visible = shown
	next_condition_button.visible = shown
	ready_button.visible = shown
	if shown:
		UiFocus.grab_later(ready_button)


## Shows the card with a heading, a text, the gauge if [param with_gauge], and a button
## labelled [param button_text] (none when empty). With the gauge the card sits in the lower
## half of the screen, so the start of the level stays visible.
func show_card(heading: String, body: String, button_text: String, with_gauge: bool) -> void:
	_card_centre.anchor_top = 0.56 if with_gauge else 0.0
	card_heading.text = heading
	card_body.text = body
	gauge.visible = with_gauge
	start_button.visible = not button_text.is_empty()
	start_button.text = button_text
	_card.show()
	if start_button.visible:
		UiFocus.grab_later(start_button)


## Hides the card.
func hide_card() -> void:
	_card.hide()


## Shows [param text] big for [param seconds].
func toast(text: String, seconds: float = 1.5) -> void:
	_toast.text = text
	_toast_left = seconds
	_toast.show()
