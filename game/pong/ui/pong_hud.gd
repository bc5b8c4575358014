class_name PongHud
extends CanvasLayer
## The Pong overlay: each player's panel (health, mines, modes, mine effect), a status
## line (serves, goals, what just happened), the force on the hand over the last 5 s
## (the peak of [code]hand_force.total[/code] since the last frame, with the contact, spin
## and effects components of the servo's state) and the controls. It reads the match each
## frame; it never changes it.

const MESSAGE_S: float = 2.0
## How far the status line moves down when four panels fill the top row (the gap between
## the panels, where it sits with two players, is then too narrow for it).
const STATUS_DROP_FOUR_PLAYERS_PX: float = 150.0
## Room between the controls line and the force plot.
const CONTROLS_GAP_PX: float = 16.0
const CONTROLS: String = (
	"WASD move  ·  mouse paddle  ·  wheel / R F depth  ·  Q E  Z C turn  ·  V spin  ·  G gun"
	+ "  ·  Space fire  ·  B mine  ·  Esc pause"
)
const KEYBOARD_CONTROLS: String = (
	"Player 2: IJKL move  ·  U O paddle down / up  ·  P swing  ·  M spin  ·  Y gun  ·  H fire"
	+ "  ·  N mine"
)

## A line the status line shows for as long as it is set (connection trouble), over flashes.
var notice: String = ""

var _panels: Array[PongPlayerPanel] = []
var _message_left: float = 0.0
var _status_top: float = 0.0
var _status_bottom: float = 0.0

@onready var _top: HBoxContainer = %Top
@onready var _status: Label = %Status
@onready var _plot: ForcePlot = %ForcePlot
@onready var _force_value: Label = %ForceValue
@onready var _components: Label = %Components
@onready var _controls: Label = %Controls
@onready var _controls_width: float = _controls.size.x
@onready var _plot_panel: Control = $Root/PlotPanel


func _ready() -> void:
	# Four panels, players 2 and 3 shown only in a four-player match: 0 and 3 (seated at -x,
	# on the left as player 0 sees the court) left, 2 (+x, on the right) and 1 right.
	for side: int in 4:
		var panel: PongPlayerPanel = PongPlayerPanel.new()
		panel.name = "Player%d" % side
		panel.visible = side < 2
		_panels.append(panel)
	var gap: Control = Control.new()
	gap.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	gap.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_top.add_child(_panels[0])
	_top.add_child(_panels[3])
	_top.add_child(gap)
	_top.add_child(_panels[2])
	_top.add_child(_panels[1])
	get_viewport().size_changed.connect(_fit_controls)
	_fit_controls.call_deferred()
	_status_top = _status.offset_top
	_status_bottom = _status.offset_bottom
	_ignore_mouse(self)


## Names, colours and health of the players (two or four: as many as [param titles]);
## [param max_force] scales the plot; [param two_players] shows the keyboard player's keys
## too.
func setup(
	titles: Array[String],
	colors: Array[Color],
	max_health: int,
	max_force: float,
	two_players: bool
) -> void:
	for side: int in _panels.size():
		_panels[side].visible = side < titles.size()
		if side < titles.size():
			_panels[side].set_player(titles[side], colors[side], max_health)
	var drop: float = STATUS_DROP_FOUR_PLAYERS_PX if titles.size() > 2 else 0.0
	_status.offset_top = _status_top + drop
	_status.offset_bottom = _status_bottom + drop
	_plot.y_max = max_force
	_controls.text = CONTROLS + ("\n" + KEYBOARD_CONTROLS if two_players else "")


## Shows [param text] on the status line for a moment.
func flash(text: String) -> void:
	_status.text = text
	_message_left = MESSAGE_S


## Refreshes everything from [param match_node].
func refresh(match_node: PongMatch, delta: float) -> void:
	for side: int in match_node.controllers.size():
		var panel: PongPlayerPanel = _panels[side]
		var intent: PongIntent = match_node.controllers[side].intent
		panel.show_health(match_node.rules.get_health(side))
		panel.show_mines(match_node.mines.left(side), match_node.mines.next_kind(side))
		panel.show_modes(intent.spin, intent.gun)
		var effect: PongEffectState = match_node.effect_of(side)
		if effect != null:
			panel.show_effect(
				PongServoFacts.PONG_EFFECT_KIND_NAMES[effect.kind], effect.remaining_s
			)
		else:
			panel.show_effect("", 0.0)
	var snapshot: PongState = match_node.snapshot
	var total: float = match_node.take_peak_force()
	_plot.advance(delta, total)
	_force_value.text = "%.2f N" % total
	_components.text = (
		"contact %.2f  ·  spin %.2f  ·  effects %.2f N"
		% [
			snapshot.hand_force.contact.length(),
			snapshot.hand_force.spin.length(),
			snapshot.hand_force.effects.length(),
		]
	)
	_message_left -= delta
	if not notice.is_empty():
		_status.text = notice
	elif _message_left <= 0.0:
		var serve_in: float = match_node.referee.time_to_serve()
		var due: bool = match_node.auto_serve and serve_in > 0.0
		_status.text = "serve in %.1f s" % serve_in if due else ""


func get_panel(side: int) -> PongPlayerPanel:
	return _panels[side]


func get_status_text() -> String:
	return _status.text


func get_plot() -> ForcePlot:
	return _plot


## Where the controls bar lies on the screen (the camera keeps the near court above it).
func get_controls_rect() -> Rect2:
	return _controls.get_global_rect()


# The mouse moves the paddle: no control of the HUD may take its motion.
static func _ignore_mouse(node: Node) -> void:
	if node is Control:
		(node as Control).mouse_filter = Control.MOUSE_FILTER_IGNORE
	for child: Node in node.get_children():
		_ignore_mouse(child)


# The controls line keeps its width where there is room and wraps left of the force plot
# where there is not (a 1024-pixel-wide window).
func _fit_controls() -> void:
	var room: float = _plot_panel.get_rect().position.x - CONTROLS_GAP_PX - _controls.offset_left
	_controls.offset_right = _controls.offset_left + minf(_controls_width, room)
