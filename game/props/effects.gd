class_name LevelEffects
extends Node2D
## The level's secondary assets: dust and sparks at impacts, splashes at the water surface
## and the sounds that go with them, all scaled by the impact speed.
##
## Props find it through the [code]effects[/code] group. Emitters and audio players come
## from fixed pools built once in [method _ready] and reused round-robin, so an impact
## never allocates nodes.

const _SOUNDS: Dictionary[StringName, AudioStream] = {
	&"wood": preload("res://assets/sounds/impact_wood.wav"),
	&"hard": preload("res://assets/sounds/impact_rock.wav"),
	&"soft": preload("res://assets/sounds/impact_soft.wav"),
	&"slippery": preload("res://assets/sounds/impact_ice.wav"),
	&"splash": preload("res://assets/sounds/splash.wav"),
	&"pearl": preload("res://assets/sounds/pearl.wav"),
	&"goal": preload("res://assets/sounds/goal.wav"),
}
const _DUST_COLORS: Dictionary[StringName, Color] = {
	&"wood": Color(0.78, 0.6, 0.38, 0.9),
	&"hard": Color(0.72, 0.76, 0.82, 0.9),
	&"soft": Color(0.93, 0.8, 0.55, 0.9),
	&"slippery": Color(0.7, 0.95, 1.0, 1.0),
}

## Impacts slower than this (pixels/second) are silent and dustless.
@export var impact_threshold: float = 60.0
## Impact speed (pixels/second) that plays at full volume and full particle count.
@export var full_impact_speed: float = 520.0
## Number of pooled dust emitters.
@export_range(1, 16) var dust_pool_size: int = 6
## Number of pooled splash emitters.
@export_range(1, 16) var splash_pool_size: int = 4
## Number of pooled positional audio players.
@export_range(1, 32) var voice_count: int = 10

var _dust: Array[GPUParticles2D] = []
var _splashes: Array[GPUParticles2D] = []
var _voices: Array[AudioStreamPlayer2D] = []
var _next_dust: int = 0
var _next_splash: int = 0
var _next_voice: int = 0
var _rng: RandomNumberGenerator = RandomNumberGenerator.new()
var _audible: bool = true

@onready var _dust_template: GPUParticles2D = $Dust
@onready var _splash_template: GPUParticles2D = $Splash


func _ready() -> void:
	add_to_group(&"effects")
	# Headless (tests, make play without a display): nothing to hear, so play nothing.
	_audible = DisplayServer.get_name() != "headless"
	_dust.append(_dust_template)
	for i: int in dust_pool_size - 1:
		var copy: GPUParticles2D = _dust_template.duplicate() as GPUParticles2D
		add_child(copy)
		_dust.append(copy)
	_splashes.append(_splash_template)
	for i: int in splash_pool_size - 1:
		var copy: GPUParticles2D = _splash_template.duplicate() as GPUParticles2D
		add_child(copy)
		_splashes.append(copy)
	for i: int in voice_count:
		var voice: AudioStreamPlayer2D = AudioStreamPlayer2D.new()
		voice.max_distance = 1800.0
		voice.bus = &"Master"
		add_child(voice)
		_voices.append(voice)


## Dust (or sparks, or splinters) and a knock at [param where], scaled by [param speed] in
## pixels/second, coloured and voiced by [param surface] (a [HapticMaterial] or null).
func impact(where: Vector2, speed: float, surface: Resource) -> void:
	if speed < impact_threshold or _dust.is_empty():
		return
	var strength: float = clampf(speed / full_impact_speed, 0.0, 1.0)
	var kind: StringName = &"hard"
	if surface != null and _SOUNDS.has(StringName(surface.resource_name)):
		kind = StringName(surface.resource_name)
	var emitter: GPUParticles2D = _dust[_next_dust]
	_next_dust = (_next_dust + 1) % _dust.size()
	emitter.global_position = where
	emitter.modulate = _DUST_COLORS.get(kind, Color.WHITE)
	emitter.amount_ratio = 0.25 + 0.75 * strength
	emitter.speed_scale = 0.7 + 0.6 * strength
	emitter.restart()
	play(kind, where, 0.15 + 0.85 * strength, _rng.randf_range(0.9, 1.1) * (1.15 - 0.3 * strength))


## Droplets and a splash sound at [param where] on a surface, scaled by [param speed].
func splash(where: Vector2, speed: float) -> void:
	if _splashes.is_empty():
		return
	var strength: float = clampf(speed / full_impact_speed, 0.15, 1.0)
	var emitter: GPUParticles2D = _splashes[_next_splash]
	_next_splash = (_next_splash + 1) % _splashes.size()
	emitter.global_position = where
	emitter.amount_ratio = 0.3 + 0.7 * strength
	emitter.speed_scale = 0.8 + 0.5 * strength
	emitter.restart()
	play(&"splash", where, 0.2 + 0.8 * strength, _rng.randf_range(0.85, 1.15))


## Plays the named sound ([code]wood, hard, soft, slippery, splash, pearl, goal[/code]) at
## [param where] with linear [param volume] and [param pitch].
func play(sound: StringName, where: Vector2, volume: float = 1.0, pitch: float = 1.0) -> void:
	var stream: AudioStream = _SOUNDS.get(sound, null)
	# Once the game is quitting no new sound starts (it would outlive the audio server's last
	# mix and leak, see CleanExit); nor does one on a voice already freed with the level.
	if stream == null or not _audible or _voices.is_empty() or CleanExit.is_quitting():
		return
	var voice: AudioStreamPlayer2D = _voices[_next_voice]
	if not voice.is_inside_tree():
		return
	_next_voice = (_next_voice + 1) % _voices.size()
	voice.stream = stream
	voice.global_position = where
	voice.volume_db = linear_to_db(clampf(volume, 0.001, 1.0))
	voice.pitch_scale = pitch
	voice.play()
