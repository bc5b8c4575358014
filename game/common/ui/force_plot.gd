class_name ForcePlot
extends Control
## A live scrolling plot of a force magnitude over the last [member window_seconds].
##
## Samples go into a [RingBuffer] at a fixed [member sample_rate] whatever the frame rate:
## [method advance] is called once per frame with the frame's time and the value seen, and
## pushes as many samples as the elapsed time spans (the largest value seen since the last
## sample, so short impacts are not lost). Nothing is allocated per frame.

## Full scale while no device reports a force limit (the Touch / Omni peak), newtons.
const FALLBACK_MAX_FORCE: float = 3.3

## Length of the visible history, in seconds.
@export var window_seconds: float = 5.0
## Samples per second kept in the ring.
@export var sample_rate: float = 60.0
## Value drawn at the top edge (the device's maximum force); larger values are clipped.
@export var y_max: float = FALLBACK_MAX_FORCE:
	set(value):
		y_max = maxf(value, 0.001)
		queue_redraw()
## Colour of the curve.
@export var line_color: Color = Color(1.0, 1.0, 1.0)
## Colour of the area under the curve.
@export var fill_color: Color = Color(0.31, 0.76, 0.97, 0.28)
@export var grid_color: Color = Color(0.56, 0.70, 0.80, 0.18)

## The samples, oldest first.
var buffer: RingBuffer = null

var _accumulated: float = 0.0
var _pending_peak: float = 0.0
var _points: PackedVector2Array = PackedVector2Array()
var _fill: PackedVector2Array = PackedVector2Array()
var _fill_indices: PackedInt32Array = PackedInt32Array()
var _fill_colors: PackedColorArray = PackedColorArray()


## The full scale for a device whose force limit is [param max_force_n] (0: none reported).
static func full_scale(max_force_n: float) -> float:
	return max_force_n if max_force_n > 0.0 else FALLBACK_MAX_FORCE


func _init() -> void:
	mouse_filter = MOUSE_FILTER_IGNORE


func _ready() -> void:
	_allocate()


## Sample capacity: [member window_seconds] times [member sample_rate].
func get_capacity() -> int:
	return maxi(2, roundi(window_seconds * sample_rate))


## Records [param value] seen during a frame of [param delta] seconds.
func advance(delta: float, value: float) -> void:
	if buffer == null:
		_allocate()
	_pending_peak = maxf(_pending_peak, value)
	_accumulated += delta
	var period: float = 1.0 / sample_rate
	var pushed: int = 0
	while _accumulated >= period:
		_accumulated -= period
		buffer.push(_pending_peak)
		pushed += 1
		if pushed >= buffer.capacity:
			_accumulated = 0.0
			break
	if pushed > 0:
		_pending_peak = value
		queue_redraw()


## Forgets the history.
func clear() -> void:
	if buffer != null:
		buffer.clear()
	_accumulated = 0.0
	_pending_peak = 0.0
	queue_redraw()


func _allocate() -> void:
	var capacity: int = get_capacity()
	if buffer == null or buffer.capacity != capacity:
		buffer = RingBuffer.new(capacity)
	_points.resize(capacity)
	_fill.resize(capacity * 2)
	# Two triangles per sample interval between the curve (even) and the baseline (odd).
	_fill_indices.resize((capacity - 1) * 6)
	for i: int in capacity - 1:
		var top: int = 2 * i
		_fill_indices[6 * i] = top
		_fill_indices[6 * i + 1] = top + 1
		_fill_indices[6 * i + 2] = top + 2
		_fill_indices[6 * i + 3] = top + 2
		_fill_indices[6 * i + 4] = top + 1
		_fill_indices[6 * i + 5] = top + 3
	_fill_colors.resize(capacity * 2)
	_fill_colors.fill(fill_color)


func _draw() -> void:
	if buffer == null:
		return
	var rect: Rect2 = Rect2(Vector2.ZERO, size)
	for fraction: float in [0.0, 0.5, 1.0]:
		var y: float = rect.size.y * (1.0 - fraction)
		draw_line(Vector2(0.0, y), Vector2(rect.size.x, y), grid_color, 1.0)
	for second: int in range(1, int(window_seconds)):
		var x: float = rect.size.x * (1.0 - float(second) / window_seconds)
		draw_line(Vector2(x, 0.0), Vector2(x, rect.size.y), grid_color, 1.0)
	var capacity: int = buffer.capacity
	var missing: int = capacity - buffer.size()
	var step: float = rect.size.x / float(capacity - 1)
	for i: int in capacity:
		var value: float = 0.0 if i < missing else buffer.get_value(i - missing)
		var y: float = rect.size.y * (1.0 - clampf(value / y_max, 0.0, 1.0))
		_points[i] = Vector2(step * float(i), y)
		_fill[2 * i] = _points[i]
		_fill[2 * i + 1] = Vector2(_points[i].x, rect.size.y)
	# The area under the curve as one triangle batch (indices built once, no triangulation).
	RenderingServer.canvas_item_add_triangle_array(
		get_canvas_item(), _fill_indices, _fill, _fill_colors
	)
	draw_polyline(_points, line_color, 2.0, true)
