class_name KeyBindingRow
extends HBoxContainer
## One button per movement direction showing its key ("Up: W"); a click asks for a key
## ("Up: press a key"), and the next key pressed is offered up through [signal key_chosen]
## (Escape cancels). The screen decides and shows the result with [method show_keys].

## The player pressed [param physical] for [param action] after clicking its button.
signal key_chosen(action: StringName, physical: Key)

var _buttons: Dictionary[StringName, Button] = {}
var _listening: StringName = &""


func _init() -> void:
	add_theme_constant_override(&"separation", 8)
	for i: int in KeyBindings.ACTIONS.size():
		var action: StringName = KeyBindings.ACTIONS[i]
		var button: Button = Button.new()
		button.theme_type_variation = &"SmallButton"
		button.tooltip_text = (
			"Click, then press the key that moves %s (the arrow keys always do)"
			% KeyBindings.NAMES[i].to_lower()
		)
		button.pressed.connect(_listen.bind(action))
		add_child(button)
		_buttons[action] = button


## Shows the keys of [param bindings] and stops waiting for a key.
func show_keys(bindings: KeyBindings) -> void:
	_listening = &""
	for i: int in KeyBindings.ACTIONS.size():
		var action: StringName = KeyBindings.ACTIONS[i]
		_buttons[action].text = (
			"%s: %s" % [KeyBindings.NAMES[i], KeyBindings.key_name(bindings.keys[action])]
		)


## Whether a button waits for its key.
func is_listening() -> bool:
	return not _listening.is_empty()


func _listen(action: StringName) -> void:
	_listening = action
	_buttons[action].text = "%s: press a key" % KeyBindings.NAMES[KeyBindings.ACTIONS.find(action)]


# Before the GUI sees it: the key pressed is the answer, not focus navigation or Back.
func _input(event: InputEvent) -> void:
	var key: InputEventKey = event as InputEventKey
	if _listening.is_empty() or key == null or not key.pressed or key.echo:
		return
	get_viewport().set_input_as_handled()
	var action: StringName = _listening
	_listening = &""
	if key.physical_keycode == KEY_ESCAPE:
		key_chosen.emit(action, KEY_NONE)
	else:
		key_chosen.emit(action, key.physical_keycode)
