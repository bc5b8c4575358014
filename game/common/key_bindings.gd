class_name KeyBindings
extends RefCounted
## The keys a player chose for moving: one key per direction beside the arrow keys, which
## always work. The defaults are the project's own input map (W, A, S, D by their place on
## the keyboard, so an AZERTY player's Z, Q, S, D); a choice replaces that key in the
## [InputMap] when [method apply] runs.

## The directions a player can rebind, as the game's input actions, and their names.
const ACTIONS: Array[StringName] = [&"move_up", &"move_down", &"move_left", &"move_right"]
const NAMES: Array[String] = ["Up", "Down", "Left", "Right"]
## Keys that keep their own job: the arrows (always move), Escape (pause, back), Enter and
## Space (menus), H (the HUD's lab view).
const RESERVED: Array[Key] = [
	KEY_UP, KEY_DOWN, KEY_LEFT, KEY_RIGHT, KEY_ESCAPE, KEY_ENTER, KEY_KP_ENTER, KEY_SPACE, KEY_H
]

## Physical keycode per action in [constant ACTIONS].
var keys: Dictionary[StringName, Key] = {}


func _init() -> void:
	reset()


## The project's own keys (its input map as saved, not as changed since).
func reset() -> void:
	for action: StringName in ACTIONS:
		keys[action] = default_key(action)


## The key of [param action] in the project's input map that is not an arrow (KEY_NONE if
## it has none).
static func default_key(action: StringName) -> Key:
	var setting: Dictionary = ProjectSettings.get_setting("input/%s" % action, {})
	for event: Object in setting.get("events", []):
		var key: InputEventKey = event as InputEventKey
		if key != null and not RESERVED.has(key.physical_keycode):
			return key.physical_keycode
	return KEY_NONE


## Binds [param physical] to [param action]; returns why not (and changes nothing), or "".
func bind(action: StringName, physical: Key) -> String:
	if not ACTIONS.has(action):
		return "'%s' cannot be rebound" % action
	if physical == KEY_NONE or RESERVED.has(physical):
		return "%s keeps its own job" % key_name(physical)
	for other: StringName in ACTIONS:
		if other != action and keys[other] == physical:
			return "%s already moves %s" % [key_name(physical), NAMES[ACTIONS.find(other)]]
	keys[action] = physical
	return ""


## Puts the chosen keys in the [InputMap] in place of the ones bound before (the arrows and
## any gamepad input stay).
func apply() -> void:
	for action: StringName in ACTIONS:
		if not InputMap.has_action(action):
			continue
		for event: InputEvent in InputMap.action_get_events(action):
			var key: InputEventKey = event as InputEventKey
			if key != null and not RESERVED.has(key.physical_keycode):
				InputMap.action_erase_event(action, event)
		var chosen: InputEventKey = InputEventKey.new()
		chosen.physical_keycode = keys[action]
		InputMap.action_add_event(action, chosen)


## Reads the keys from [param section] of [param file]. A missing section keeps the defaults;
## a set with an unknown, reserved or repeated key is refused whole (the defaults stay):
## returns why, or "".
func read(file: ConfigFile, section: String) -> String:
	reset()
	var chosen: Dictionary[StringName, Key] = {}
	for action: StringName in ACTIONS:
		var value: Variant = file.get_value(section, action, keys[action])
		if typeof(value) != TYPE_INT:
			return "the key for %s is not a key" % NAMES[ACTIONS.find(action)]
		var code: int = value
		chosen[action] = code as Key
	for action: StringName in ACTIONS:
		keys[action] = KEY_NONE
	for action: StringName in ACTIONS:
		var why: String = bind(action, chosen[action])
		if not why.is_empty():
			reset()
			return why
	return ""


func write(file: ConfigFile, section: String) -> void:
	for action: StringName in ACTIONS:
		file.set_value(section, action, int(keys[action]))


## The key's name on this keyboard's layout ("W", or "Z" on an AZERTY keyboard).
static func key_name(physical: Key) -> String:
	if physical == KEY_NONE:
		return "no key"
	# Without a display (headless) there is no layout to ask: the QWERTY name.
	if DisplayServer.get_name() == "headless":
		return OS.get_keycode_string(physical)
	return OS.get_keycode_string(DisplayServer.keyboard_get_keycode_from_physical(physical))
