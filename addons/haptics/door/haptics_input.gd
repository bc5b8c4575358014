extends RefCounted
## The Haptics door's input side: the user's keys, buttons, sticks and mouse move the
## simulated device's hand, and the device's input vector is fed into input actions as
## strengths. The door owns one, forwards its two settings ([member hand_actions],
## [member feed_actions]) and decides when each part runs (control mode, whether the hand
## follows the user).

## Fed strengths up to this release the action even where the action's deadzone is smaller
## (a centred device presses nothing).
const FEED_THRESHOLD := 0.05
## The mouse stick's full deflection, as a fraction of the viewport's height.
const MOUSE_STICK_REACH := 0.25

## The actions (left, right, up, down) that move the simulated hand; empty: none. An
## action the project does not define counts as released.
var hand_actions: PackedStringArray = []:
	set(value):
		hand_actions = _checked_actions(value, "hand_actions", hand_actions)
		_hand_actions_complete = not hand_actions.is_empty()
		for action: String in hand_actions:
			_hand_actions_complete = _hand_actions_complete and InputMap.has_action(action)
## The actions (left, right, up, down) [method feed] presses; empty: none.
var feed_actions: PackedStringArray = []:
	set(value):
		release_fed()
		feed_actions = _checked_actions(value, "feed_actions", feed_actions)

var _stick_held: bool = false
var _stick_origin: Vector2 = Vector2.ZERO
# The actions this door pressed and has not released.
var _fed: Dictionary[String, bool] = {}
var _hand_actions_complete: bool = false


## Takes note of [param event] wherever it goes: a left-button release lets go of the mouse
## stick (even over a control).
func notice(event: InputEvent) -> void:
	var button: InputEventMouseButton = event as InputEventMouseButton
	if button != null and button.button_index == MOUSE_BUTTON_LEFT and not button.pressed:
		_stick_held = false


## Takes note of [param event] that no control took: a left-button press in the game grips
## the mouse stick where it is.
func notice_unhandled(event: InputEvent) -> void:
	var button: InputEventMouseButton = event as InputEventMouseButton
	if button != null and button.button_index == MOUSE_BUTTON_LEFT and button.pressed:
		_stick_held = true
		_stick_origin = button.position


## Lets go of the mouse stick (the window lost the focus, so its release may never come).
func release_mouse_stick() -> void:
	_stick_held = false


## The mouse stick in [param viewport] as the player holds it now.
func mouse_stick(viewport: Viewport) -> HapticsMouseStick:
	var stick: HapticsMouseStick = HapticsMouseStick.new()
	stick.held = _stick_held
	stick.origin = _stick_origin
	stick.pointer = viewport.get_mouse_position()
	stick.radius = viewport.get_visible_rect().size.y * MOUSE_STICK_REACH
	return stick


## Presses [member feed_actions] as far as [param input_vector] points their way, as a stick
## would: an action is pressed (for [method Input.is_action_pressed]) only past its deadzone
## ([method InputMap.action_get_deadzone]), with the deflection itself as its strength.
## Not [param driven] (the device does not drive the player): releases them instead.
func feed(input_vector: Vector2, driven: bool = true) -> void:
	if not driven:
		release_fed()
		return
	var i: Vector2 = input_vector
	var strengths: PackedFloat32Array = [
		maxf(-i.x, 0.0), maxf(i.x, 0.0), maxf(-i.y, 0.0), maxf(i.y, 0.0)
	]
	for k: int in feed_actions.size():
		var action: String = feed_actions[k]
		if not InputMap.has_action(action):
			continue
		# Input.action_press marks the action pressed at any strength: a 0.05 drift of the
		# hand would be a full key press to a game reading is_action_pressed.
		var deadzone: float = maxf(FEED_THRESHOLD, InputMap.action_get_deadzone(action))
		if strengths[k] > deadzone:
			# The stronger wins: a key held down keeps its full strength.
			Input.action_press(action, maxf(strengths[k], _physical_strength(action)))
			_fed[action] = true
		elif _fed.has(action):
			_let_go(action)


## Releases every action [method feed] pressed.
func release_fed() -> void:
	for action: String in _fed.keys():
		_let_go(action)


# Takes back what this door pressed into [param action]. Input.action_release releases the
# action whatever else holds it, and a key held down sends no second press: the keys, buttons
# and sticks still holding it press it again at their strength.
func _let_go(action: String) -> void:
	_fed.erase(action)
	if not InputMap.has_action(action):
		return
	var held: float = _physical_strength(action)
	if held > 0.0:
		Input.action_press(action, held)
	else:
		Input.action_release(action)


## Where the user puts the simulated hand (normalised): keyboard/gamepad deflection wins;
## otherwise, while the mouse stick is held, the pointer's offset from where it was
## gripped ([constant MOUSE_STICK_REACH] of its height being the workspace edge); else the centre.
func hand_target(viewport: Viewport) -> Vector2:
	var keys: Vector2 = Vector2.ZERO
	if _hand_actions_complete and feed_actions.is_empty():
		keys = Input.get_vector(hand_actions[0], hand_actions[1], hand_actions[2], hand_actions[3])
	elif not hand_actions.is_empty():
		keys = Vector2(
			_action_strength(1) - _action_strength(0), _action_strength(3) - _action_strength(2)
		)
		keys = keys.limit_length(1.0)
	if not keys.is_zero_approx():
		return keys
	return mouse_stick(viewport).deflection()


# Four actions or none; an empty name is no action, names the project lacks are reported once;
# both count as released.
func _checked_actions(
	actions: PackedStringArray, what: String, kept: PackedStringArray
) -> PackedStringArray:
	if not actions.is_empty() and actions.size() != 4:
		push_error(
			(
				"Haptics.%s: give four actions (left, right, up, down) or none, not %s; keeping %s."
				% [what, actions, kept]
			)
		)
		return kept
	var missing: PackedStringArray = []
	for action: String in actions:
		if not action.is_empty() and not InputMap.has_action(action):
			missing.append(action)
	if not missing.is_empty():
		push_warning("Haptics.%s: no input action %s in this project." % [what, missing])
	return actions


func _action_strength(index: int) -> float:
	var action: String = hand_actions[index]
	if not InputMap.has_action(action):
		return 0.0
	return (
		_physical_strength(action)
		if not feed_actions.is_empty()
		else Input.get_action_strength(action)
	)


# How far the keys, buttons and sticks bound to [param action] are pressed, without what
# this door fed into it (reading the action itself, the hand would hold itself down).
func _physical_strength(action: String) -> float:
	var strength: float = 0.0
	for event: InputEvent in InputMap.action_get_events(action):
		var key: InputEventKey = event as InputEventKey
		var button: InputEventJoypadButton = event as InputEventJoypadButton
		var motion: InputEventJoypadMotion = event as InputEventJoypadMotion
		var mouse: InputEventMouseButton = event as InputEventMouseButton
		if key != null:
			var down: bool = (
				(
					key.physical_keycode != KEY_NONE
					and Input.is_physical_key_pressed(key.physical_keycode)
				)
				or (key.keycode != KEY_NONE and Input.is_key_pressed(key.keycode))
			)
			strength = maxf(strength, 1.0 if down else 0.0)
		elif mouse != null and Input.is_mouse_button_pressed(mouse.button_index):
			strength = 1.0
		for pad: int in Input.get_connected_joypads():
			if button != null and Input.is_joy_button_pressed(pad, button.button_index):
				strength = 1.0
			elif motion != null and signf(motion.axis_value) != 0.0:
				var along: float = Input.get_joy_axis(pad, motion.axis) * signf(motion.axis_value)
				if along > InputMap.action_get_deadzone(action):
					strength = maxf(strength, minf(along, 1.0))
	return strength
