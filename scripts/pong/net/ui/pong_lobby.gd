class_name PongLobby
extends CanvasLayer
## The network game's lobby, opened from the Pong setup: host or join (name, address,
## port), the players with their seats and whether they are ready, Ready, Start (the
## host, once everyone is ready), Leave, Back. The match itself runs in the [PongScreen]
## that [PongNet] makes; its winner screen's Play again readies up for a rematch and its
## Menu leaves the game. It only talks to [PongNet] (signal up, call down).

## Back to the Pong setup (the session is closed).
signal back_requested

var net: PongNet = null

var _name_edit: LineEdit = LineEdit.new()
var _address_edit: LineEdit = LineEdit.new()
var _port_spin: SpinBox = SpinBox.new()
var _host_button: Button = Button.new()
var _join_button: Button = Button.new()
var _ready_check: CheckButton = CheckButton.new()
var _start_button: Button = Button.new()
var _leave_button: Button = Button.new()
var _back_button: Button = Button.new()
var _status: Label = Label.new()
var _players: Label = Label.new()
var _panel: PanelContainer = PanelContainer.new()


func _ready() -> void:
	layer = 25
	process_mode = Node.PROCESS_MODE_ALWAYS
	_build()
	net = get_tree().root.get_node_or_null(PongNet.NODE_NAME) as PongNet
	if net == null:
		net = PongNet.new()
		net.name = PongNet.NODE_NAME
		get_tree().root.add_child.call_deferred(net)
	net.status_changed.connect(_on_status)
	net.lobby_changed.connect(_refresh)
	net.match_started.connect(_on_match_started)
	net.match_ended.connect(_on_match_ended)
	_refresh()


func _exit_tree() -> void:
	if net != null and is_instance_valid(net):
		net.leave()
		net.close_screen()
		net.queue_free()


func _build() -> void:
	var root: Control = Control.new()
	root.set_anchors_preset(Control.PRESET_FULL_RECT)
	root.theme = load("res://assets/ui/theme.tres") as Theme
	add_child(root)
	var center: CenterContainer = CenterContainer.new()
	center.set_anchors_preset(Control.PRESET_FULL_RECT)
	root.add_child(center)
	_panel.custom_minimum_size = Vector2(560, 0)
	center.add_child(_panel)
	var column: VBoxContainer = VBoxContainer.new()
	_panel.add_child(column)
	var heading: Label = Label.new()
	heading.text = "Network game"
	column.add_child(heading)
	_name_edit.placeholder_text = "Your name"
	_name_edit.text = "Player"
	_name_edit.max_length = PongNetProtocol.MAX_NAME_LENGTH
	_address_edit.placeholder_text = "Host address (to join)"
	_address_edit.text = "127.0.0.1"
	_port_spin.min_value = 1024
	_port_spin.max_value = 65535
	_port_spin.value = PongNetProtocol.DEFAULT_PORT
	_port_spin.prefix = "Port"
	for control: Control in [_name_edit, _address_edit, _port_spin]:
		column.add_child(control)
	var row: HBoxContainer = HBoxContainer.new()
	column.add_child(row)
	_host_button.text = "Host"
	_join_button.text = "Join"
	row.add_child(_host_button)
	row.add_child(_join_button)
	_status.autowrap_mode = TextServer.AUTOWRAP_WORD
	_status.text = "Host a game, or join one by its address."
	column.add_child(_status)
	column.add_child(_players)
	_ready_check.text = "Ready"
	_start_button.text = "Start the match"
	_leave_button.text = "Leave"
	_back_button.text = "Back"
	for control: Control in [_ready_check, _start_button, _leave_button, _back_button]:
		column.add_child(control)
	_host_button.pressed.connect(_on_host)
	_join_button.pressed.connect(_on_join)
	_ready_check.toggled.connect(func(on: bool) -> void: net.set_ready(on))
	_start_button.pressed.connect(func() -> void: net.start_match())
	_leave_button.pressed.connect(_on_leave)
	_back_button.pressed.connect(_on_back)
	UiFocus.grab_later(_host_button)


func _on_host() -> void:
	net.my_name = _player_name()
	net.host(int(_port_spin.value))


func _on_join() -> void:
	net.my_name = _player_name()
	net.join(_address_edit.text.strip_edges(), int(_port_spin.value))


func _on_leave() -> void:
	net.leave()
	_status.text = "Left the game."
	_refresh()


func _on_back() -> void:
	net.leave()
	back_requested.emit()


func _player_name() -> String:
	var text: String = _name_edit.text.strip_edges()
	return text if not text.is_empty() else "Player"


func _on_status(text: String) -> void:
	_status.text = text
	_refresh()


func _refresh() -> void:
	if net == null:
		return
	var connected: bool = net.session.is_open()
	_host_button.disabled = connected
	_join_button.disabled = connected
	_ready_check.disabled = not connected
	_leave_button.disabled = not connected
	_start_button.visible = net.session.is_server
	_start_button.disabled = not net.can_start()
	var lines: PackedStringArray = PackedStringArray()
	for peer: int in net.players:
		var entry: Dictionary = net.players[peer]
		var seat: int = entry["seat"]
		var is_ready: bool = entry["ready"]
		lines.append(
			"Seat %d: %s%s" % [seat + 1, str(entry["name"]), " (ready)" if is_ready else ""]
		)
	_players.text = "\n".join(lines) if not lines.is_empty() else "No players yet."
	var mine: Dictionary = net.players.get(net.my_id(), {})
	var mine_ready: bool = mine.get("ready", false)
	_ready_check.set_pressed_no_signal(mine_ready)


func _on_match_started() -> void:
	visible = false
	var screen: PongScreen = net.screen
	if screen == null:
		return
	screen.pause_menu.enabled = false
	screen.play_again_requested.connect(_on_rematch)
	screen.menu_requested.connect(_on_leave_match)


func _on_match_ended(_winner: int, why: String) -> void:
	if why != "over":
		net.close_screen()
		visible = true
		get_tree().paused = false
	_refresh()


func _on_rematch() -> void:
	get_tree().paused = false
	net.close_screen()
	visible = true
	net.set_ready(true)
	_refresh()


func _on_leave_match() -> void:
	get_tree().paused = false
	net.close_screen()
	net.leave()
	visible = true
	_refresh()
