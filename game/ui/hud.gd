class_name Hud
extends CanvasLayer
## The in-game overlay. [constant View.COMPACT] (the default) shows the run's time and items
## in one small panel, and the mouse stick while it is held. [constant View.LAB] adds the
## rendered force as arrows by component around a small avatar glyph (and at the player's
## screen position), with a colour legend; a scrolling plot of |total force| over the last
## 5 s; the device name and servo rate; the simulated device's position against the hand
## target. The [code]lab_view[/code] action (H) switches between them.
##
## Every control ignores the mouse, which moves the simulated device's hand target. With
## [member live] on, the HUD polls the [code]Haptics[/code] autoload each frame; tests turn
## it off and call [method show_forces] directly.

## The player switched the view with the lab_view action.
signal view_changed(view: View)

enum View { COMPACT, LAB }

## Components listed in the legend, in order.
const LEGEND_ORDER: Array[String] = [
	"normal", "friction", "weight", "drag", "inertia", "impact", "total"
]
## Magnification of the diagram around the avatar glyph: its ring stands for the device's
## maximum force divided by this (game forces are mostly well below the maximum); the
## arrows at the player use the plain scale (ring = maximum force).
const DIAGRAM_ZOOM: float = 2.0
## Seconds between refreshes of the text labels.
const LABEL_PERIOD: float = 0.25

## Poll the haptics every frame (off in tests, which feed [method show_forces]).
@export var live: bool = true
## Draw the force arrows at the player's screen position too (in the lab view).
@export var arrows_at_player: bool = true
## What it shows; the run panel sits at the top in the compact view and at the bottom in
## the lab view, clear of the lab panels at every window size.
@export var view: View = View.COMPACT:
	set(value):
		view = value
		if is_node_ready():
			_show_view()

var _player: Node2D = null
var _legend_values: Dictionary[String, Label] = {}
var _total_magnitude: float = 0.0
var _label_timer: float = 0.0

@onready var _arrows: ForceArrows = %ForceArrows
@onready var _world_arrows: ForceArrows = %WorldArrows
@onready var _plot: ForcePlot = %ForcePlot
@onready var _device: DeviceWidget = %DeviceWidget
@onready var _legend: VBoxContainer = %Legend
@onready var _magnitude: Label = %Magnitude
@onready var _forces_caption: Label = %ForcesCaption
@onready var _plot_scale: Label = %PlotScale
@onready var _device_name: Label = %DeviceName
@onready var _servo: Label = %Servo
@onready var _control: Label = %Control
@onready var _time: Label = %TimeValue
@onready var _items: Label = %ItemsValue
@onready var _forces_panel: Control = %ForcesPanel
@onready var _right_column: Control = %RightColumn
@onready var _run_panel: Control = %RunPanel
@onready var _view_hint: Label = %ViewHint


func _ready() -> void:
	_build_legend()
	_ignore_mouse(self)
	_show_view()
	set_max_force(ForcePlot.full_scale(Haptics.device.get_max_force()))
	set_run_info(0.0, 0, -1)
	_refresh_labels()


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"lab_view"):
		view = View.LAB if view == View.COMPACT else View.COMPACT
		view_changed.emit(view)
		get_viewport().set_input_as_handled()


func _process(delta: float) -> void:
	if live:
		show_forces(Haptics.get_forces())
		_device.set_positions(Haptics.device.get_position(), Haptics.device.get_hand_target())
		_label_timer -= delta
		if _label_timer <= 0.0:
			_label_timer = LABEL_PERIOD
			_refresh_labels()
	_plot.advance(delta, _total_magnitude)
	_follow_player()


## Shows one tick's [HapticForces] (the movement renderer's components, game axes):
## arrows, legend values and |total|.
func show_forces(forces: HapticForces) -> void:
	_arrows.set_forces(forces)
	_world_arrows.set_forces(forces)
	var components: Dictionary[String, Vector2] = ForceArrows.components_of(forces)
	for component: String in _legend_values:
		_legend_values[component].text = "%.2f N" % components[component].length()
	_total_magnitude = forces.total.length()
	_magnitude.text = "%.2f N" % _total_magnitude


## Scales arrows and plot so that [param newtons] (the device's maximum force) fills them.
func set_max_force(newtons: float) -> void:
	_arrows.max_force = newtons / DIAGRAM_ZOOM
	_world_arrows.max_force = newtons
	_plot.y_max = newtons
	_plot_scale.text = "top = %.1f N (device max)" % newtons
	_forces_caption.text = "FORCE ON THE HAND  ·  ring = %.2f N" % _arrows.max_force


## Shows the arrows at [param player]'s screen position as well (null to stop).
func set_player(player: Node2D) -> void:
	_player = player
	_follow_player()


## Shows the run's elapsed time and items; [param total] below 0 means unknown.
func set_run_info(seconds: float, collected: int, total: int) -> void:
	_time.text = GoalScreen.format_time(seconds)
	_items.text = GoalScreen.format_items(collected, total)


## Shows how the player steers (e.g. "haptic device (mouse)", "keyboard", "autopilot").
func set_control_text(text: String) -> void:
	_control.text = "control: %s" % text


## The arrows drawn at the player.
func get_world_arrows() -> ForceArrows:
	return _world_arrows


## The |total force| plot.
func get_plot() -> ForcePlot:
	return _plot


## The device position / hand target widget.
func get_device_widget() -> DeviceWidget:
	return _device


## The legend's value label of [param component] (null if unknown).
func get_legend_value(component: String) -> Label:
	return _legend_values.get(component, null)


## The HUD's servo line while the servo runs: its rate, period p99 and which real-time
## techniques it was granted ([method HapticsServo.get_stats]): the real-time priority (from
## RealtimeKit for a normal user) or what the servo has without one, locked memory, the CPU
## latency held, the pinned CPU, the spin before each deadline ("learned" when it is this
## machine's wake-up lateness, without the latency hold).
static func servo_running_text(rate_hz: float, stats: HapticServoStats) -> String:
	var p99_ms: float = stats.period_p99_s * 1e3
	var parts: PackedStringArray = ["servo %d Hz" % roundi(rate_hz), "p99 %.2f ms" % p99_ms]
	if stats.realtime:
		var via_rtkit: bool = stats.scheduler == HapticRealtime.SchedulerKind.REALTIME_RR
		parts.append("RT %d%s" % [stats.realtime_priority, " (RealtimeKit)" if via_rtkit else ""])
	else:
		var without: String = realtime_missing_text(stats)
		if not without.is_empty():
			parts.append(without)
	if stats.memory_locked:
		parts.append("mlock")
	if stats.cpu_latency_held:
		parts.append("C-states held")
	if stats.pinned_cpu >= 0:
		parts.append("CPU %d" % stats.pinned_cpu)
	var spin_us: float = stats.spin_s * 1e6
	if spin_us > 0.0:
		var learned: String = " (learned)" if stats.spin_learned else ""
		parts.append("spin %d µs%s" % [roundi(spin_us), learned])
	return "  ·  ".join(parts)


## Without real time, what the servo has instead and the one step that gives more, from
## what RealtimeKit answered; "" when it was not asked.
static func realtime_missing_text(stats: HapticServoStats) -> String:
	var grant: HapticRealtimeKitGrant = stats.realtime_kit
	match grant.outcome:
		HapticRealtime.RtkitOutcome.HIGH_PRIORITY:
			return "nice %d (no real time outside a desktop session)" % grant.nice
		HapticRealtime.RtkitOutcome.REFUSED:
			return "no real time: RealtimeKit refused (no desktop session?)"
		HapticRealtime.RtkitOutcome.UNAVAILABLE:
			return "no real time: install rtkit (sudo apt install rtkit)"
	return ""


## The HUD's servo line when the servo is not running: why, and what happens now.
## What the player is told while the device takes no output ("" while it does): the servo
## runs, but the device holds the last force it took.
static func device_stuck_text(device_status: HapticDeviceStatus) -> String:
	if device_status.output_stuck_s <= 0.0:
		return ""
	return (
		"device not taking force for %.1f s: it holds the last one" % device_status.output_stuck_s
	)


## The hint line, always on screen: how to switch views, and in the compact view a device
## that takes no force ([method device_stuck_text]).
static func view_hint_text(lab: bool, stuck: String) -> String:
	if lab:
		return "H: hide the lab view"
	return "H: lab view (forces, device)" if stuck.is_empty() else "%s  ·  H: more" % stuck


static func servo_stopped_text(servo_status: String, device_status: HapticDeviceStatus) -> String:
	if servo_status.is_empty():
		return "servo off"
	var reason: String = device_status.reason
	if device_status.io == HapticDeviceKinds.DeviceIo.DISCONNECTED:
		return (
			"device unplugged%s: zero force, playing on the keyboard; plug it back in to resume"
			% ("" if reason.is_empty() else " (%s)" % reason)
		)
	return "servo stopped: %s" % servo_status


func _show_view() -> void:
	var lab: bool = view == View.LAB
	_forces_panel.visible = lab
	_right_column.visible = lab
	_view_hint.text = view_hint_text(lab, "")
	# Top centre in the compact view; bottom centre under the lab view's two top panels.
	var height: float = _run_panel.offset_bottom - _run_panel.offset_top
	var top: float = 16.0 if not lab else -16.0 - height
	_run_panel.anchor_top = 0.0 if not lab else 1.0
	_run_panel.anchor_bottom = _run_panel.anchor_top
	_run_panel.offset_top = top
	_run_panel.offset_bottom = top + height
	_follow_player()


func _follow_player() -> void:
	var follow: bool = (
		view == View.LAB and arrows_at_player and _player != null and is_instance_valid(_player)
	)
	_world_arrows.visible = follow
	if follow:
		_world_arrows.position = _player.get_global_transform_with_canvas().origin


func _refresh_labels() -> void:
	var device: String = Haptics.device.get_name()
	if not Haptics.is_available():
		device = "No haptics extension"
	elif device.is_empty():
		device = "No device open"
	_device_name.text = device
	var rate: float = Haptics.servo.get_rate_hz()
	var status: HapticDeviceStatus = Haptics.device.get_status()
	var stuck: String = device_stuck_text(status)
	if rate > 0.0:
		_servo.text = servo_running_text(rate, Haptics.servo.get_stats())
		_servo.text = stuck if not stuck.is_empty() else _servo.text
	else:
		_servo.text = servo_stopped_text(Haptics.servo.get_status(), status)
	_view_hint.text = view_hint_text(view == View.LAB, stuck)


func _build_legend() -> void:
	for component: String in LEGEND_ORDER:
		var row: HBoxContainer = HBoxContainer.new()
		row.add_theme_constant_override(&"separation", 8)
		var swatch: ColorRect = ColorRect.new()
		swatch.color = ForceArrows.COLORS[component]
		swatch.custom_minimum_size = Vector2(16, 5)
		swatch.size_flags_vertical = Control.SIZE_SHRINK_CENTER
		var name_label: Label = Label.new()
		name_label.theme_type_variation = &"HudLabel"
		name_label.text = ForceArrows.LABELS[component]
		name_label.custom_minimum_size = Vector2(100, 0)
		var value_label: Label = Label.new()
		value_label.theme_type_variation = &"HudLabel"
		value_label.text = "0.00 N"
		value_label.custom_minimum_size = Vector2(62, 0)
		value_label.horizontal_alignment = HORIZONTAL_ALIGNMENT_RIGHT
		row.add_child(swatch)
		row.add_child(name_label)
		row.add_child(value_label)
		_legend.add_child(row)
		_legend_values[component] = value_label


static func _ignore_mouse(node: Node) -> void:
	if node is Control:
		(node as Control).mouse_filter = Control.MOUSE_FILTER_IGNORE
	for child: Node in node.get_children():
		_ignore_mouse(child)
