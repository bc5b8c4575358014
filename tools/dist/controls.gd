extends SceneTree
## Prints the player README's controls tables (Markdown) from the project's input map, so
## the README names the keys the game really binds.
##   tools/godot --headless --path . -s tools/dist/controls.gd

## Each table: its heading, then rows of what an action does and the action's name.
const TABLES: Array[Array] = [
	[
		"Side-scroller and maze study (the simulated stylus; a force-feedback device replaces it)",
		[
			[
				"move the hand left / right / up / down",
				[&"move_left", &"move_right", &"move_up", &"move_down"]
			],
			["pause menu", [&"pause"]],
		],
	],
	[
		"Haptic Battle Pong, player 1 (near)",
		[
			["move the avatar", [&"move_left", &"move_right", &"move_up", &"move_down"]],
			["paddle in depth (push / pull)", [&"paddle_push", &"paddle_pull"]],
			["turn the paddle (yaw)", [&"paddle_yaw_left", &"paddle_yaw_right"]],
			["tilt the paddle", [&"paddle_tilt_up", &"paddle_tilt_down"]],
			[
				"spin paddle / gun / fire / mine",
				[&"spin_toggle", &"gun_toggle", &"fire", &"place_mine"]
			],
			["pause", [&"pause"]],
		],
	],
	[
		"Haptic Battle Pong, player 2 (far, keyboard)",
		[
			["move the avatar", [&"p1_left", &"p1_right", &"p1_up", &"p1_down"]],
			["paddle lower / raise, swing", [&"p1_paddle_down", &"p1_paddle_up", &"p1_swing"]],
			[
				"spin paddle / gun / fire / mine",
				[&"p1_spin_toggle", &"p1_gun_toggle", &"p1_fire", &"p1_place_mine"]
			],
		],
	],
]


func _initialize() -> void:
	var missing: PackedStringArray = []
	var out: PackedStringArray = []
	for table: Array in TABLES:
		out.append("### " + str(table[0]))
		out.append("")
		out.append("| action | keyboard / mouse | gamepad |")
		out.append("|---|---|---|")
		for row: Array in table[1]:
			var keys: PackedStringArray = []
			var pads: PackedStringArray = []
			for action: StringName in row[1]:
				if not InputMap.has_action(action):
					missing.append(action)
					continue
				keys.append(_names(action, false))
				pads.append(_names(action, true))
			out.append("| %s | %s | %s |" % [row[0], " / ".join(keys), " / ".join(pads)])
		out.append("")
	if not missing.is_empty():
		printerr("controls: actions not in the input map: " + ", ".join(missing))
		quit(1)
		return
	print("\n".join(out))
	quit(0)


# The events bound to an action, keyboard and mouse or gamepad ones, joined with "or".
func _names(p_action: StringName, p_gamepad: bool) -> String:
	var names: PackedStringArray = []
	for event: InputEvent in InputMap.action_get_events(p_action):
		var is_pad: bool = event is InputEventJoypadButton or event is InputEventJoypadMotion
		if is_pad != p_gamepad:
			continue
		var key: InputEventKey = event as InputEventKey
		if key != null:
			var code: Key = (
				key.physical_keycode if key.physical_keycode != KEY_NONE else key.keycode
			)
			names.append(OS.get_keycode_string(code))
		elif is_pad:
			# "Joypad Button 0 (Bottom Action, Sony Cross, ...)": the first name that is
			# not a raw "Joystick N" axis, else the first.
			var text: String = event.as_text()
			var inside: String = text.substr(text.find("(") + 1).get_slice(")", 0)
			var parts: PackedStringArray = inside.split(", ")
			var name: String = parts[0]
			for part: String in parts:
				if not part.begins_with("Joystick"):
					name = part
					break
			var motion: InputEventJoypadMotion = event as InputEventJoypadMotion
			if motion != null:
				name += " +" if motion.axis_value > 0.0 else " −"
			names.append(name)
		else:
			names.append(event.as_text())
	return " or ".join(names) if not names.is_empty() else "–"
