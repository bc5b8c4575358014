extends "res://tests/net/lobby_suite.gd"
## The lobby's form: every input has a visible label it is tied to, Tab walks the form in
## reading order, the Seats choice reaches [member PongNet.seats] when hosting (and a bad
## choice is refused), the lobby lists the open seats, and the keyboard focus leaves a
## button that hosting disabled.


func test_every_field_has_a_visible_label_tied_to_it() -> void:
	var expected: Dictionary[Control, String] = {
		_lobby._name_edit: "Your name",
		_lobby._port_spin: "Port",
		_lobby._seats_option: "Seats",
		_lobby._address_edit: "Host address",
	}
	for field: Control in expected:
		var label: Label = _lobby.label_of(field)
		assert_not_null(label, "%s has a label" % expected[field])
		if label == null:
			continue
		assert_eq(label.text, expected[field])
		assert_true(label.is_visible_in_tree(), "%s label is shown" % label.text)
		assert_eq(field.get_node(field.accessibility_labeled_by_nodes[0]), label)
		assert_false(field.tooltip_text.is_empty(), "%s has a tooltip" % label.text)
	assert_null(_lobby.label_of(_lobby._back_button), "a button is its own label")


func test_tab_walks_the_form_in_reading_order() -> void:
	var order: Array[Control] = [
		_lobby._name_edit,
		_lobby._port_spin.get_line_edit(),
		_lobby._seats_option,
		_lobby._host_button,
		_lobby._address_edit,
		_lobby._join_button,
	]
	for i: int in order.size() - 1:
		var next: Control = order[i].find_next_valid_focus()
		assert_eq(next, order[i + 1], "Tab from step %d" % i)


func test_the_seats_choice_reaches_pong_net_when_hosting() -> void:
	var net: PongNet = _lobby.net
	assert_eq(_lobby.chosen_seats(), 2, "two seats unless the host asks for four")
	assert_true(_lobby.choose_seats(4))
	assert_eq(_lobby.chosen_seats(), 4)
	_lobby._port_spin.value = _port()
	_lobby._host_button.pressed.emit()
	assert_true(net.session.is_server, _lobby._status.text)
	assert_eq(net.seats, 4)
	assert_true(_lobby._seats_option.disabled, "the choice is fixed while hosting")
	var lines: PackedStringArray = _lobby._players.text.split("\n")
	assert_eq(lines.size(), 4, _lobby._players.text)
	assert_true(lines[0].begins_with("Seat 1: Host"), lines[0])
	assert_true(lines[3].contains("Seat 4: open"), lines[3])
	net.leave()
	assert_false(_lobby._seats_option.disabled)
	assert_true(_lobby.choose_seats(2))
	_lobby._host_button.pressed.emit()
	assert_eq(net.seats, 2, "hosting again takes the new choice")
	assert_eq(_lobby._players.text.split("\n").size(), 2, _lobby._players.text)
	net.leave()


func test_a_seat_count_that_is_not_offered_is_refused() -> void:
	assert_true(_lobby.choose_seats(4))
	expect_error("3 seats is not a choice")
	assert_false(_lobby.choose_seats(3))
	assert_eq(_lobby.chosen_seats(), 4, "the choice is left as it was")


func test_hosting_moves_the_focus_from_host_to_ready_and_leaving_back() -> void:
	_lobby._host_button.grab_focus()
	_lobby._port_spin.value = _port()
	_lobby._host_button.pressed.emit()
	await get_tree().process_frame
	assert_eq(get_viewport().gui_get_focus_owner(), _lobby._ready_check)
	_lobby._leave_button.grab_focus()
	_lobby._leave_button.pressed.emit()
	await get_tree().process_frame
	assert_eq(get_viewport().gui_get_focus_owner(), _lobby._host_button)
