class_name PongLobby
extends CanvasLayer
## The network game's lobby, shown over the Pong setup by the main scene: host or join
## (name, address, port), the players with their seats and whether they are ready, Ready,
## Start (the host, once everyone is ready), Leave, Back. The match itself runs in the
## [PongScreen] that [PongNet] makes; its winner screen's Play again readies up for a
## rematch and its Menu leaves the game. It only talks to [PongNet] (signal up, call down).

## Back to the Pong setup (the session is closed).
signal back_requested

## The court sizes a host can choose, in the order of the Seats choice.
const SEAT_CHOICES: Array[int] = [2, 4]
## The names of players who leave the name field empty.
const HOST_NAME: String = "Host"
const GUEST_NAME: String = "Guest"
const STARTING_TEXT: String = "Starting the match…"
## Where this player's identity is kept: a game restarted after a crash joins the running
## match again in its old seat ([PongNetRejoins]).
const IDENTITY_PATH: String = "user://pong_net_identity.txt"

var net: PongNet = null

var _name_edit: LineEdit = LineEdit.new()
var _address_edit: LineEdit = LineEdit.new()
var _port_spin: SpinBox = SpinBox.new()
var _seats_option: OptionButton = OptionButton.new()
var _host_button: Button = Button.new()
var _join_button: Button = Button.new()
var _ready_check: CheckButton = CheckButton.new()
var _start_button: Button = Button.new()
var _leave_button: Button = Button.new()
var _back_button: Button = Button.new()
var _status: Label = Label.new()
var _players: Label = Label.new()
var _panel: PanelContainer = PanelContainer.new()
# Start was pressed and the match is about to load.
var _starting: bool = false
# Each input field's visible label, by field.
var _labels: Dictionary[Control, Label] = {}


func _ready() -> void:
	layer = 25
	process_mode = Node.PROCESS_MODE_ALWAYS
	_build()
	net = get_tree().root.get_node_or_null(PongNet.NODE_NAME) as PongNet
	if net == null:
		net = PongNet.new()
		net.name = PongNet.NODE_NAME
		get_tree().root.add_child.call_deferred(net)
	net.rejoins.identity = PongNetRejoins.lasting(IDENTITY_PATH)
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


func _unhandled_input(event: InputEvent) -> void:
	if visible and event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		_on_back()


## The visible label of [param field] (an input of the form), or null.
func label_of(field: Control) -> Label:
	return _labels.get(field, null)


## How many seats the Seats choice asks for (2 or 4).
func chosen_seats() -> int:
	return SEAT_CHOICES[maxi(_seats_option.selected, 0)]


## Sets the Seats choice to [param seats] (2 or 4; anything else is refused and
## leaves the choice as it was). Returns whether it was taken.
func choose_seats(seats: int) -> bool:
	var index: int = SEAT_CHOICES.find(seats)
	if index < 0:
		push_error("PongLobby: %d seats is not a choice (%s)" % [seats, SEAT_CHOICES])
		return false
	_seats_option.select(index)
	return true


func _build() -> void:
	var root: Control = Control.new()
	root.set_anchors_preset(Control.PRESET_FULL_RECT)
	root.theme = load("res://assets/ui/theme.tres") as Theme
	add_child(root)
	var center: CenterContainer = CenterContainer.new()
	center.set_anchors_preset(Control.PRESET_FULL_RECT)
	root.add_child(center)
	_panel.custom_minimum_size = Vector2(600, 0)
	center.add_child(_panel)
	var column: VBoxContainer = VBoxContainer.new()
	column.add_theme_constant_override(&"separation", 8)
	_panel.add_child(column)
	var heading: Label = Label.new()
	heading.text = "Network game"
	heading.theme_type_variation = &"HeadingLabel"
	column.add_child(heading)
	column.add_child(_build_form())
	_status.autowrap_mode = TextServer.AUTOWRAP_WORD
	_status.theme_type_variation = &"SubtitleLabel"
	_status.text = "Host a game, or join one by its address."
	column.add_child(_status)
	_players.accessibility_live = DisplayServer.LIVE_POLITE
	column.add_child(_players)
	_ready_check.text = "Ready"
	_ready_check.tooltip_text = "Ready for the match: the host starts it once everyone is."
	_start_button.text = "Start the match"
	_leave_button.text = "Leave"
	_leave_button.tooltip_text = "Leave this game and stay in the lobby."
	_back_button.text = "Back"
	# Two buttons a row: a four-seat lobby still fits a 720-pixel-high window.
	for pair: Array[Control] in [
		[_ready_check, _start_button] as Array[Control],
		[_leave_button, _back_button] as Array[Control],
	]:
		var row: HBoxContainer = HBoxContainer.new()
		row.add_theme_constant_override(&"separation", 12)
		column.add_child(row)
		for control: Control in pair:
			control.size_flags_horizontal = Control.SIZE_EXPAND_FILL
			control.size_flags_stretch_ratio = 1.0
			row.add_child(control)
	_host_button.pressed.connect(_on_host)
	_join_button.pressed.connect(_on_join)
	_address_edit.text_submitted.connect(func(_text: String) -> void: _on_join())
	_ready_check.toggled.connect(func(on: bool) -> void: net.set_ready(on))
	_start_button.pressed.connect(_on_start)
	_leave_button.pressed.connect(_on_leave)
	_back_button.pressed.connect(_on_back)
	UiFocus.grab_later(_host_button)


# Label | field | action, one row each, in the order Tab walks them: who you are, the port
# both ways use, then what hosting needs next to Host and what joining needs next to Join.
func _build_form() -> GridContainer:
	var form: GridContainer = GridContainer.new()
	form.columns = 3
	form.add_theme_constant_override(&"h_separation", 12)
	form.add_theme_constant_override(&"v_separation", 8)
	_name_edit.placeholder_text = "%s or %s" % [HOST_NAME, GUEST_NAME]
	_name_edit.max_length = PongNetProtocol.MAX_NAME_LENGTH
	_name_edit.tooltip_text = (
		"Your name, as the other players see it (up to %d characters; empty: %s or %s)."
		% [PongNetProtocol.MAX_NAME_LENGTH, HOST_NAME, GUEST_NAME]
	)
	_port_spin.min_value = 1024
	_port_spin.max_value = 65535
	_port_spin.value = PongNetProtocol.DEFAULT_PORT
	_port_spin.tooltip_text = "UDP port: the host listens on it, the others connect to it."
	for seats: int in SEAT_CHOICES:
		_seats_option.add_item(
			"%d, face to face" % seats if seats == 2 else "%d, square court" % seats
		)
	_seats_option.tooltip_text = (
		"How many sides the court has. The computer plays the seats nobody takes; "
		+ "players who join get the host's choice."
	)
	_address_edit.text = "127.0.0.1"
	_address_edit.tooltip_text = "The host's IP address or name, to join its game."
	_host_button.text = "Host"
	_host_button.tooltip_text = "Host a game on this machine, on the port above."
	_join_button.text = "Join"
	_join_button.tooltip_text = "Join the game hosted at this address and port."
	_add_row(form, "Your name", _name_edit, null)
	_add_row(form, "Port", _port_spin, null)
	_add_row(form, "Seats", _seats_option, _host_button)
	_add_row(form, "Host address", _address_edit, _join_button)
	return form


func _add_row(form: GridContainer, text: String, field: Control, action: Button) -> void:
	var label: Label = Label.new()
	label.text = text
	form.add_child(label)
	field.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	form.add_child(field)
	if action == null:
		form.add_child(Control.new())
	else:
		action.custom_minimum_size = Vector2(110, 0)
		form.add_child(action)
	field.accessibility_labeled_by_nodes = [field.get_path_to(label)]
	_labels[field] = label


func _on_host() -> void:
	net.my_name = _player_name(HOST_NAME)
	net.seats = chosen_seats()
	net.host(int(_port_spin.value))


func _on_join() -> void:
	net.my_name = _player_name(GUEST_NAME)
	net.join(_address_edit.text.strip_edges(), int(_port_spin.value))


func _on_leave() -> void:
	net.leave()
	_status.text = "Left the game."
	_refresh()


func _on_back() -> void:
	net.leave()
	back_requested.emit()


func _player_name(default: String) -> String:
	var text: String = _name_edit.text.strip_edges()
	return text if not text.is_empty() else default


# Loading the court stalls this peer for a moment: the lobby says so, and draws it, first.
func _on_start() -> void:
	if not net.can_start():
		return
	_starting = true
	_start_button.disabled = true
	_status.text = STARTING_TEXT
	for frame: int in 2:
		await get_tree().process_frame
	_starting = false
	if not net.start_match():
		_refresh()


func _on_status(text: String) -> void:
	_status.text = text
	_refresh()


func _refresh() -> void:
	if net == null:
		return
	var connected: bool = net.session.is_open()
	_host_button.disabled = connected
	_join_button.disabled = connected
	# In a game the form shows what the game runs with: nothing there can change it.
	_name_edit.editable = not connected
	_address_edit.editable = not connected
	_port_spin.editable = not connected
	_seats_option.disabled = connected
	if connected and SEAT_CHOICES.has(net.seats):
		_seats_option.select(SEAT_CHOICES.find(net.seats))
	_ready_check.disabled = not connected
	_leave_button.disabled = not connected
	_start_button.visible = net.session.is_server
	_start_button.disabled = _starting or not net.can_start()
	_players.text = _player_lines() if connected else "No players yet."
	var mine: Dictionary = net.players.get(net.my_id(), {})
	var mine_ready: bool = mine.get("ready", false)
	_ready_check.set_pressed_no_signal(mine_ready)
	_keep_focus_usable(connected)


# One line a seat: who sits there and whether they are ready; the computer plays the rest.
func _player_lines() -> String:
	if net.players.is_empty():
		return "No players yet."
	var by_seat: Dictionary[int, Dictionary] = {}
	var seat_count: int = net.seats
	for entry: Dictionary in net.players.values():
		var taken: int = entry["seat"]
		by_seat[taken] = entry
		seat_count = maxi(seat_count, taken + 1)
	var lines: PackedStringArray = PackedStringArray()
	for seat: int in seat_count:
		if not by_seat.has(seat):
			lines.append("Seat %d: open (the computer plays it)" % (seat + 1))
			continue
		var entry: Dictionary = by_seat[seat]
		var is_ready: bool = entry["ready"]
		lines.append(
			"Seat %d: %s%s" % [seat + 1, str(entry["name"]), " (ready)" if is_ready else ""]
		)
	return "\n".join(lines)


# Hosting or joining disables the button that has the focus: the keyboard goes on from
# Ready (in a game) or Host (out of one) instead of from a dead button.
func _keep_focus_usable(connected: bool) -> void:
	if not is_inside_tree() or not visible:
		return
	var focused: BaseButton = get_viewport().gui_get_focus_owner() as BaseButton
	if focused != null and (focused.disabled or not focused.is_visible_in_tree()):
		UiFocus.grab_later(_ready_check if connected else _host_button)


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
