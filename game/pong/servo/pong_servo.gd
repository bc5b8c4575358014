class_name PongServo
extends RefCounted
## Haptic Battle Pong's renderer in the servo, as the game reaches it: the ball simulated at
## 1 kHz, its contact with every paddle, spin, the effects on the hand, and the events it
## reports. A typed face over the framework's generic renderer door
## ([code]Haptics.renderer(&"pong")[/code]) with the values of the renderer's schema
## ([code]gdextension/src/renderers/pong/pong.schema.toml[/code], generated beside this
## script). World vectors are Godot [Vector3] in metres (y up); hand forces are device space,
## newtons. Without the native extension [method is_available] is false and every answer is
## neutral: there is no ball then (the game says so; it never simulates the ball itself).

## The Pong renderer started or stopped.
signal changed

## The renderer's name in the servo.
const NAME := &"pong"
## Frequency of a mine's rumble, Hz: high, so it buzzes rather than pushes.
const RUMBLE_FREQUENCY_HZ: float = 180.0
## Servo period of [method step_ticks], seconds (the 1 kHz tick).
const TICK_S: float = 0.001
## How long after it is sent a command has surely reached the servo: at its next tick, or
## the one after when it came during a tick, s. A state or event older than that predates it.
const COMMAND_LANDS_S: float = 1.5 * TICK_S
## [method apply_effect]'s strength meaning "the servo's own for the kind" (slow: no cap on
## its viscous force; the others: their [code]pong.*_force_n[/code]).
const DEFAULT_STRENGTH: float = -1.0
## [method apply_effect]'s default owner: the player across the court
## ([method opponent_across]).
const OWNER_ACROSS: int = -1
# The door's script by its path: a door of a test's own is typed the same as the autoload.
const Haptics := preload("res://addons/haptics/door/haptics.gd")

static var _shared: PongServo = null

var _haptics: Haptics = null
var _renderer: HapticsRenderer = null
var _previous_mode: StringName = &""


func _init(haptics: Haptics) -> void:
	_haptics = haptics
	_renderer = haptics.renderer(NAME)
	_renderer.changed.connect(changed.emit)


## The Pong renderer of the [code]Haptics[/code] autoload, made on first use.
static func shared() -> PongServo:
	if _shared == null:
		var tree: SceneTree = Engine.get_main_loop() as SceneTree
		_shared = PongServo.new(tree.root.get_node(^"/root/Haptics") as Haptics)
	return _shared


## True when the extension is loaded and has the Pong renderer.
func is_available() -> bool:
	return _renderer.is_available()


## Switches the servo to the Pong renderer (the previous one is restored by [method leave]).
func enter() -> bool:
	if not is_available():
		return false
	if _previous_mode.is_empty():
		_previous_mode = _haptics.get_render_mode()
	return _renderer.activate()


## Back to the renderer that was active before [method enter].
func leave() -> void:
	if not is_available() or _previous_mode.is_empty():
		return
	clear_effects()
	_haptics.set_render_mode(_previous_mode)
	_previous_mode = &""
	changed.emit()


## Whether the Pong renderer is the servo's current one.
func is_active() -> bool:
	return _renderer.is_active()


## The renderer's settings now (court, ball, contact, spin, effects): a copy to read, or to
## change and hand to [method apply_settings]; the defaults without the extension.
func get_settings() -> PongSettings:
	var settings: PongSettings = PongSettings.decode(_renderer.settings_bytes())
	return settings if settings != null else PongSettings.new()


## Hands the renderer [param settings] whole; refused ones are reported, naming the field,
## and change nothing.
func apply_settings(settings: PongSettings) -> bool:
	return _renderer.apply_settings(settings)


## Hands the servo this update's input: every player's avatar and paddle, who holds the
## device, beginner mode.
func set_input(input: PongInput) -> bool:
	return _renderer.send(input)


## Puts the ball at [param position] with [param velocity] and [param spin] (a serve).
func set_ball(position: Vector3, velocity: Vector3, spin: Vector3 = Vector3.ZERO) -> bool:
	return _send_ball(PongServoFacts.PongCommandType.SET_BALL, position, velocity, spin)


## Corrects the ball toward [param position], [param velocity] and [param spin] (where it
## should be now, a network update): the servo blends it in over the next ticks while the
## ball flies on, never jumping ([code]pong.correction_*[/code] settings).
func correct_ball(position: Vector3, velocity: Vector3, spin: Vector3 = Vector3.ZERO) -> bool:
	return _send_ball(PongServoFacts.PongCommandType.CORRECT_BALL, position, velocity, spin)


## Starts an effect on [param player]'s hand (it acts only on the device player's):
## [param kind] one of [constant PongServoFacts.PONG_EFFECT_KIND_NAMES]; [param magnitude_n]
## its strength (a cap for slow and remote) or [constant DEFAULT_STRENGTH]; [param direction]
## (world, any length but zero) for recoil and hit; [param owner] the player whose stylus a
## remote mine pulls toward, by default ([constant OWNER_ACROSS]) the player across the
## court. A command the servo would refuse (an unknown kind or player, an owner that is no
## other player, a recoil or hit without a direction, a negative or non-finite strength or a
## duration not above zero) is refused here with an error naming it, and nothing is sent.
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
		push_error("PongServo.apply_effect: %s; nothing was sent." % refusal)
		return false
	var command: PongCommand = PongCommand.new()
	command.type = PongServoFacts.PongCommandType.EFFECT
	command.player = player
	var kind_index: int = PongServoFacts.PONG_EFFECT_KIND_NAMES.find(kind)
	command.kind = kind_index as PongServoFacts.PongEffectKind
	command.direction = direction
	command.duration_s = duration_s
	command.use_default_duration = false
	command.owner = resolved
	command.use_default_magnitude = magnitude_n == DEFAULT_STRENGTH
	command.magnitude_n = 0.0 if command.use_default_magnitude else magnitude_n
	return _renderer.send(command)


## The player across the court from [param player] (0 and 1, 2 and 3): the servo's own
## default owner of an effect.
static func opponent_across(player: int) -> int:
	return player ^ 1


## Ends every effect at once.
func clear_effects() -> bool:
	var command: PongCommand = PongCommand.new()
	command.type = PongServoFacts.PongCommandType.CLEAR_EFFECTS
	return _renderer.send(command)


## The newest servo state (a ball at rest at the origin without the extension).
func get_state() -> PongState:
	var state: PongState = PongState.decode(_renderer.read(PongState.SCHEMA_ID))
	return state if state != null else PongState.new()


## The server's check of a state of its master's ball against its own simulation of the
## ball: the verdict, or null without the extension.
func check_ball(check: PongWitnessCheck) -> PongWitnessVerdict:
	if not _renderer.send(check):
		return null
	return PongWitnessVerdict.decode(_renderer.read(PongWitnessVerdict.SCHEMA_ID))


## A pose of a paddle the master of the ball drives, for [method check_ball].
func note_master_pose(pose: PongWitnessPose) -> bool:
	return _renderer.send(pose)


## The events since the last call, oldest first.
func drain_events() -> Array[PongEvent]:
	var batch: PongEventBatch = PongEventBatch.decode(_renderer.read(PongEventBatch.SCHEMA_ID))
	return batch.events if batch != null else ([] as Array[PongEvent])


## The device player's running effect of [param kind] in [param state], or null.
static func effect_in(state: PongState, kind: String) -> PongEffectState:
	for effect: PongEffectState in state.effects:
		if PongServoFacts.PONG_EFFECT_KIND_NAMES[effect.kind] == kind:
			return effect
	return null


## Moves the simulated device's hand to [param target_m] (device space, metres: x right,
## y up, z toward the user), kept within the workspace radius.
func set_hand_target_3d(target_m: Vector3) -> bool:
	return is_available() and _haptics.device.set_hand_target_3d(target_m)


## A mine's rumble on the hand: the impact transient, at a high frequency, of
## [param strength_n] newtons peak, decaying over [param decay_s].
func rumble(strength_n: float, decay_s: float) -> bool:
	if not is_available():
		return false
	var impact: HapticImpact = HapticImpact.new()
	impact.direction = Vector2.UP
	# A = gain * speed: a unit speed makes the gain the peak force.
	impact.speed_m_per_s = 1.0
	impact.material = HapticImpactMaterial.new()
	impact.material.gain_n_s_per_m = strength_n
	impact.material.frequency_hz = RUMBLE_FREQUENCY_HZ
	impact.material.decay_s = decay_s
	return _haptics.push_impact(impact)


## Runs [param ticks] servo ticks on this thread (the servo thread must be stopped): a
## headless match then runs faster than real time.
func step_ticks(ticks: int) -> bool:
	if not is_available() or _haptics.servo.is_running():
		return false
	for i: int in ticks:
		if not _haptics.servo.step(TICK_S):
			return false
	return true


func _send_ball(
	type: PongServoFacts.PongCommandType, position: Vector3, velocity: Vector3, spin: Vector3
) -> bool:
	var command: PongCommand = PongCommand.new()
	command.type = type
	command.position = position
	command.velocity = velocity
	command.spin = spin
	return _renderer.send(command)


# Why the servo would refuse this effect ("" when it would not): the checks it makes that
# do not depend on its limits (those stay its own).
func _effect_refusal(
	player: int, kind: String, magnitude_n: float, duration_s: float, direction: Vector3, owner: int
) -> String:
	var count: int = get_settings().players
	if not PongServoFacts.PONG_EFFECT_KIND_NAMES.has(kind):
		var kinds: String = ", ".join(PongServoFacts.PONG_EFFECT_KIND_NAMES)
		return "unknown kind '%s' (one of %s)" % [kind, kinds]
	if player < 0 or player >= count:
		return "player must be 0..%d on this court (got %d)" % [count - 1, player]
	if owner < 0 or owner >= count:
		return "owner must be 0..%d on this court (got %d)" % [count - 1, owner]
	if kind == "remote" and owner == player:
		return "a remote effect's owner must be another player than %d" % player
	return _effect_value_refusal(kind, magnitude_n, duration_s, direction)


# Why the servo would refuse an effect's direction, strength or duration ("" when it would
# not).
func _effect_value_refusal(
	kind: String, magnitude_n: float, duration_s: float, direction: Vector3
) -> String:
	var directed: bool = kind == "recoil" or kind == "hit"
	if directed and (direction.is_zero_approx() or not direction.is_finite()):
		return "a %s needs a direction (got %s)" % [kind, direction]
	var strength_ok: bool = magnitude_n == DEFAULT_STRENGTH or magnitude_n >= 0.0
	if not is_finite(magnitude_n) or not strength_ok:
		return "magnitude_n must be a finite number >= 0 or DEFAULT_STRENGTH (got %s)" % magnitude_n
	if not is_finite(duration_s) or duration_s <= 0.0:
		return "duration_s must be a finite number > 0 (got %s)" % duration_s
	return ""
