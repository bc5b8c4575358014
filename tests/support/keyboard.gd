class_name TestKeyboard
extends RefCounted
## Keys as a keyboard sends them: key events, pressed and let go, through Godot's input (the
## door reads the keys themselves, and the actions follow).


## Sends [param key] pressed, or let go.
static func send(key: Key, pressed: bool) -> void:
	var event: InputEventKey = InputEventKey.new()
	event.keycode = key
	event.physical_keycode = key
	event.pressed = pressed
	Input.parse_input_event(event)
