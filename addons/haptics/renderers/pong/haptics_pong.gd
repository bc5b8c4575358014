class_name HapticsPong
extends RefCounted
## The Haptic Battle Pong side of the [code]Haptics[/code] door ([code]Haptics.pong[/code]):
## the servo's third renderer, which simulates the ball at 1 kHz, its contact with both
## paddles, spin, the effects on the hand, and reports events. World vectors are Godot
## [Vector3] in metres (y up); hand forces are in device space, newtons. Without the native
## extension [method is_available] is false and every answer is neutral: there is no ball
## then (the game says so; it never simulates the ball itself).

## The Pong renderer started or stopped.
signal changed

## Effect kinds of [method apply_effect] (the servo's names).
const EFFECT_KINDS: Array[String] = ["recoil", "hit", "slow", "heavy", "remote", "none"]
## Frequency of a mine's rumble, Hz: high, so it buzzes rather than pushes.
const RUMBLE_FREQUENCY_HZ: float = 180.0
## Servo period of [method step_ticks], seconds (the 1 kHz tick).
const TICK_S: float = 0.001
## [method apply_effect]'s strength meaning "the servo's own for the kind" (slow: no cap on
## its viscous force; the others: their [code]pong.*_force_n[/code]).
const DEFAULT_STRENGTH: float = -1.0
## [method apply_effect]'s default owner: the player across the court
## ([method opponent_across]).
const OWNER_ACROSS: int = -1

var _server: Object = null
var _servo: HapticsServo = null
var _render_mode_constant: int = 0
var _previous_mode: int = -1


func _init(server: Object, servo: HapticsServo, render_mode_constant: int) -> void:
	_server = server
	_servo = servo
	_render_mode_constant = render_mode_constant


## True when the extension is loaded and has the Pong renderer.
func is_available() -> bool:
	return _server != null and _server.has_method(&"set_pong_input")


## Switches the servo to the Pong renderer (the previous one is restored by
## [method leave]).
func enter() -> bool:
	if not is_available():
		return false
	if _previous_mode < 0:
		_previous_mode = _server.call(&"get_render_mode")
	var accepted: bool = _server.call(&"set_render_mode", _render_mode_constant)
	changed.emit()
	return accepted


## Back to the renderer that was active before [method enter].
func leave() -> void:
	if not is_available() or _previous_mode < 0:
		return
	_server.call(&"pong_command", {"type": "clear_effects"})
	_server.call(&"set_render_mode", _previous_mode)
	_previous_mode = -1
	changed.emit()


## Whether the Pong renderer is the servo's current one.
func is_active() -> bool:
	if not is_available():
		return false
	var mode: int = _server.call(&"get_render_mode")
	return mode == _render_mode_constant


## The [code]"pong"[/code] configuration section (court, ball, contact, spin, effects);
## empty without the extension.
func get_config() -> Dictionary:
	if not is_available():
		return {}
	var config: Dictionary = _server.call(&"get_config")
	return config.get("pong", {})


## Changes keys of the [code]"pong"[/code] configuration; refused values change nothing.
func configure(values: Dictionary) -> bool:
	return is_available() and _server.call(&"set_config", "pong", values)


## Hands the servo this update's input: every player's avatar and paddle, who holds the
## device, beginner mode.
func set_input(input: HapticPongInput) -> bool:
	return is_available() and _server.call(&"set_pong_input", input.to_dictionary())


## Puts the ball at [param position] with [param velocity] and [param spin] (a serve).
func set_ball(position: Vector3, velocity: Vector3, spin: Vector3 = Vector3.ZERO) -> bool:
	return _command({"type": "set_ball", "position": position, "velocity": velocity, "spin": spin})


## Corrects the ball toward [param position], [param velocity] and [param spin] (where it
## should be now, a network update): the servo blends it in over the next ticks while the
## ball flies on, never jumping ([code]pong.correction_*[/code] settings).
func correct_ball(position: Vector3, velocity: Vector3, spin: Vector3 = Vector3.ZERO) -> bool:
	return _command(
		{"type": "correct_ball", "position": position, "velocity": velocity, "spin": spin}
	)


## Starts an effect on [param player]'s hand (it acts only on the device player's):
## [param kind] one of [constant EFFECT_KINDS]; [param magnitude_n] its strength (a cap
## for slow and remote) or [constant DEFAULT_STRENGTH]; [param direction] (world, any length
## but zero) for recoil and hit; [param owner] the player whose stylus a remote mine pulls
## toward, by default ([constant OWNER_ACROSS]) the player across the court. A command the
## servo would refuse (an unknown kind or player, an owner that is no other player, a
## recoil or hit without a direction, a negative or non-finite strength or a duration not
## above zero) is refused here with an error naming it, and nothing is sent.
func apply_effect(
	player: int,
	kind: String,
	magnitude_n: float,
	duration_s: float,
	direction: Vector3 = Vector3.ZERO,
	owner: int = OWNER_ACROSS
) -> bool:
	if not is_available():
		return false
	var resolved: int = opponent_across(player) if owner == OWNER_ACROSS else owner
	var refusal: String = _effect_refusal(
		player, kind, magnitude_n, duration_s, direction, resolved
	)
	if not refusal.is_empty():
		push_error("Haptics.pong.apply_effect: %s; nothing was sent." % refusal)
		return false
	var command: Dictionary = {
		"type": "effect",
		"player": player,
		"kind": kind,
		"direction": direction,
		"duration_s": duration_s,
		"owner": resolved,
	}
	if magnitude_n != DEFAULT_STRENGTH:
		command["magnitude_n"] = magnitude_n
	return _command(command)


## The player across the court from [param player] (0 and 1, 2 and 3): the servo's own
## default owner of an effect.
static func opponent_across(player: int) -> int:
	return player ^ 1


## Ends every effect at once.
func clear_effects() -> bool:
	return _command({"type": "clear_effects"})


## The newest servo state (a ball at rest at the origin without the extension).
func get_state() -> HapticPongState:
	var state: Dictionary = _server.call(&"get_pong_state") if is_available() else {}
	return HapticPongState.from_dictionary(state)


## The events since the last call, oldest first: {type (floor, wall, paddle, release,
## territory), time_s, position, speed, territory, player, wall}.
func drain_events() -> Array[Dictionary]:
	var events: Array[Dictionary] = []
	if is_available():
		var drained: Array = _server.call(&"drain_pong_events")
		events.assign(drained)
	return events


## Moves the simulated device's hand to [param target_m] (device space, metres: x right,
## y up, z toward the user), kept within the workspace radius.
func set_hand_target_3d(target_m: Vector3) -> bool:
	if not is_available():
		return false
	var limits: Dictionary = _server.call(&"get_device_limits")
	var radius: float = limits.get("workspace_radius_m", 0.0)
	return _server.call(&"set_hand_target_3d", target_m.limit_length(radius))


## A mine's rumble on the hand: the existing impact transient, at a high frequency, of
## [param strength_n] newtons peak, decaying over [param decay_s].
func rumble(strength_n: float, decay_s: float) -> bool:
	if not is_available():
		return false
	var ring: HapticMaterial = HapticMaterial.new()
	ring.impact_gain = strength_n
	ring.impact_frequency = RUMBLE_FREQUENCY_HZ
	ring.impact_decay = decay_s
	# A = gain * speed: a unit speed makes the gain the peak force.
	var impact: HapticImpact = HapticImpact.new(Vector2.UP, 1.0, ring)
	return _server.call(&"push_impact", impact.to_dictionary())


## Runs [param ticks] servo ticks on this thread (the servo thread must be stopped): a
## headless match then runs faster than real time.
func step_ticks(ticks: int) -> bool:
	if not is_available() or _servo.is_running():
		return false
	for i: int in ticks:
		if not _server.call(&"step", TICK_S):
			return false
	return true


# Why the servo would refuse this effect ("" when it would not): the checks it makes that
# do not depend on its limits (those stay its own).
func _effect_refusal(
	player: int, kind: String, magnitude_n: float, duration_s: float, direction: Vector3, owner: int
) -> String:
	var whose: String = _players_refusal(player, kind, owner)
	if not whose.is_empty():
		return whose
	var directed: bool = kind == "recoil" or kind == "hit"
	if directed and (direction.is_zero_approx() or not direction.is_finite()):
		return "a %s needs a direction (got %s)" % [kind, direction]
	var strength_ok: bool = magnitude_n == DEFAULT_STRENGTH or magnitude_n >= 0.0
	if not is_finite(magnitude_n) or not strength_ok:
		return "magnitude_n must be a finite number >= 0 or DEFAULT_STRENGTH (got %s)" % magnitude_n
	if not is_finite(duration_s) or duration_s <= 0.0:
		return "duration_s must be a finite number > 0 (got %s)" % duration_s
	return ""


# Why the kind, player or owner of an effect would be refused ("" when they would not).
func _players_refusal(player: int, kind: String, owner: int) -> String:
	var count_value: float = get_config().get("players", 2.0)
	var count: int = roundi(count_value)
	if not EFFECT_KINDS.has(kind):
		return "unknown kind '%s' (one of %s)" % [kind, ", ".join(PackedStringArray(EFFECT_KINDS))]
	if player < 0 or player >= count:
		return "player must be 0..%d on this court (got %d)" % [count - 1, player]
	if owner < 0 or owner >= count:
		return "owner must be 0..%d on this court (got %d)" % [count - 1, owner]
	if kind == "remote" and owner == player:
		return "a remote effect's owner must be another player than %d" % player
	return ""


func _command(command: Dictionary) -> bool:
	return is_available() and _server.call(&"pong_command", command)
