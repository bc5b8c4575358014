class_name PongSounds
extends Node
## The match's sounds, each made here from a few lines of arithmetic (no recorded file):
## a paddle's tock, a bounce's thud, the gun's shot, a bullet's hit, a mine landing and a
## mine going off. [method listen] plays them on a match's signals; paddle contacts and
## bounces are louder the faster the ball meets them.

## A sound started: [param sound] one of the keys of [constant RECIPES].
signal played(sound: StringName)

const PADDLE: StringName = &"paddle"
const BOUNCE: StringName = &"bounce"
const SHOT: StringName = &"shot"
const HIT: StringName = &"hit"
const MINE_PLACED: StringName = &"mine_placed"
const MINE_BLAST: StringName = &"mine_blast"
## Samples per second of the made sounds: enough for tones up to 10 kHz.
const MIX_RATE: int = 22050
## Each sound's recipe: a tone sweeping from from_hz to to_hz, mixed with low-passed noise
## (its share of the mix), length_s long, fading with the time constant decay_s. High and
## short for the paddle's wood, low and noisy for the floor, a falling sweep for the gun, a
## long low rumble for a mine.
const RECIPES: Dictionary[StringName, Dictionary] = {
	PADDLE: {"from_hz": 640.0, "to_hz": 560.0, "noise": 0.2, "length_s": 0.09, "decay_s": 0.025},
	BOUNCE: {"from_hz": 190.0, "to_hz": 130.0, "noise": 0.35, "length_s": 0.14, "decay_s": 0.04},
	SHOT: {"from_hz": 1600.0, "to_hz": 320.0, "noise": 0.15, "length_s": 0.16, "decay_s": 0.06},
	HIT: {"from_hz": 260.0, "to_hz": 90.0, "noise": 0.7, "length_s": 0.22, "decay_s": 0.07},
	MINE_PLACED:
	{"from_hz": 900.0, "to_hz": 1250.0, "noise": 0.0, "length_s": 0.07, "decay_s": 0.02},
	MINE_BLAST: {"from_hz": 75.0, "to_hz": 40.0, "noise": 0.85, "length_s": 0.6, "decay_s": 0.18},
}
## The peak of a made sound, as a share of full scale (headroom for overlaps).
const PEAK: float = 0.7
## The ball's speed (m/s) at which a contact's sound is at full volume; slower is quieter,
## down to [constant QUIETEST_DB].
const FULL_VOLUME_SPEED_M_PER_S: float = 4.0
const QUIETEST_DB: float = -18.0
## How many of one sound may ring at once.
const POLYPHONY: int = 4
# Against a click at the start: the sound rises over this long.
const _ATTACK_S: float = 0.002
# The noise's one-pole low-pass: the share of a new random value per sample.
const _NOISE_SMOOTHING: float = 0.35

var _players: Dictionary[StringName, AudioStreamPlayer] = {}


func _ready() -> void:
	for sound: StringName in RECIPES:
		var player: AudioStreamPlayer = AudioStreamPlayer.new()
		player.name = String(sound).to_pascal_case()
		player.stream = make_stream(RECIPES[sound], hash(sound))
		player.max_polyphony = POLYPHONY
		add_child(player)
		_players[sound] = player


## The sound of [param recipe] (one of [constant RECIPES]), 16-bit mono at
## [constant MIX_RATE]; [param seed_value] makes its noise.
static func make_stream(recipe: Dictionary, seed_value: int) -> AudioStreamWAV:
	var length_s: float = recipe["length_s"]
	var from_hz: float = recipe["from_hz"]
	var to_hz: float = recipe["to_hz"]
	var noise_share: float = recipe["noise"]
	var decay_s: float = recipe["decay_s"]
	var count: int = roundi(length_s * MIX_RATE)
	var data: PackedByteArray = PackedByteArray()
	data.resize(count * 2)
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = seed_value
	var phase: float = 0.0
	var noise: float = 0.0
	for i: int in count:
		var t: float = float(i) / MIX_RATE
		phase += TAU * lerpf(from_hz, to_hz, float(i) / count) / MIX_RATE
		noise = lerpf(noise, rng.randf_range(-1.0, 1.0), _NOISE_SMOOTHING)
		var envelope: float = exp(-t / decay_s) * minf(1.0, t / _ATTACK_S)
		var sample: float = (sin(phase) * (1.0 - noise_share) + noise * noise_share) * envelope
		data.encode_s16(i * 2, clampi(roundi(sample * PEAK * 32767.0), -32768, 32767))
	var stream: AudioStreamWAV = AudioStreamWAV.new()
	stream.format = AudioStreamWAV.FORMAT_16_BITS
	stream.mix_rate = MIX_RATE
	stream.stereo = false
	stream.data = data
	return stream


## Plays [param sound] at [param loudness] (0: [constant QUIETEST_DB], 1: full).
func play(sound: StringName, loudness: float = 1.0) -> void:
	var player: AudioStreamPlayer = _players.get(sound)
	if player == null:
		push_error("PongSounds.play: unknown sound '%s'." % sound)
		return
	player.volume_db = lerpf(QUIETEST_DB, 0.0, clampf(loudness, 0.0, 1.0))
	player.play()
	played.emit(sound)


## The player of [param sound] (null for an unknown one).
func get_player(sound: StringName) -> AudioStreamPlayer:
	return _players.get(sound)


## Plays the sounds of [param match_node]'s contacts, bounces, bullets and mines.
func listen(match_node: PongMatch) -> void:
	match_node.event_seen.connect(_on_event)
	match_node.bullet_fired.connect(func(_bullet: PongBullets.Bullet) -> void: play(SHOT))
	match_node.bullet_hit.connect(func(_hit: Dictionary) -> void: play(HIT))
	match_node.mine_placed.connect(func(_mine: PongMines.Mine) -> void: play(MINE_PLACED))
	match_node.mine_exploded.connect(
		func(_mine: PongMines.Mine, _victim: int) -> void: play(MINE_BLAST)
	)


func _on_event(event: PongEvent) -> void:
	var loudness: float = event.speed / FULL_VOLUME_SPEED_M_PER_S
	match event.type:
		PongServoFacts.PongEventType.PADDLE:
			play(PADDLE, loudness)
		PongServoFacts.PongEventType.FLOOR, PongServoFacts.PongEventType.WALL:
			play(BOUNCE, loudness)
