class_name HapticsRendererFace
extends RefCounted
## What a renderer's typed face ([HapticsMovement], [HapticsConstraint]) shares: the generic
## door into the renderer ([HapticsRenderer]) it wraps, whether the library has it, and making
## it the servo's. Each face adds its name, its [code]of()[/code], and its own values.

var _renderer: HapticsRenderer = null


func _init(renderer: HapticsRenderer) -> void:
	_renderer = renderer


## Whether the native library has it.
func is_available() -> bool:
	return _renderer.is_available()


## Makes it the servo's renderer (the previous one stops; this one starts from rest).
func activate() -> bool:
	return _renderer.activate()


## Whether it is the servo's renderer now.
func is_active() -> bool:
	return _renderer.is_active()
