class_name HapticsRenderer
extends RefCounted
## One of the servo's renderers, by name ([code]Haptics.renderer(&"constraint")[/code]): make
## it the active one, send it values of its own schema, read the values it gives. What only
## that renderer offers (the constraint renderer's walls, Pong's ball) is defined in its own
## folder, C++ and GDScript; this door into it is the same for every renderer, so neither the
## framework nor the native library names any of them.

## It became the active renderer or stopped being it, or its settings were applied.
signal changed

const HapticsBackend := preload("res://addons/haptics/door/haptics_backend.gd")

## The renderer's name ([code]movement[/code], [code]constraint[/code], [code]pong[/code]...).
var renderer_name: StringName = &""

var _backend: HapticsBackend = null
var _mode: int = -1


func _init(backend: HapticsBackend, name: StringName) -> void:
	_backend = backend
	renderer_name = name
	_mode = backend.renderer_names().find(name)


## Whether the native library has this renderer.
func is_available() -> bool:
	return _mode >= 0


## Makes it the servo's renderer (the previous one stops; the new one starts from rest).
func activate() -> bool:
	if not is_available():
		return false
	if is_active():
		return true
	var accepted: bool = _backend.set_render_mode(_mode)
	changed.emit()
	return accepted


## Whether it is the servo's renderer now.
func is_active() -> bool:
	return is_available() and _backend.render_mode() == _mode


## Hands it [param value], one of the values its schema says it takes; a value it refuses is
## reported, naming the field, and changes nothing.
func send(value: HapticsValue) -> bool:
	return is_available() and _backend.renderer_send(_mode, value.encode())


## The bytes of the value of layout [param value_id] it gives (its class's
## [code]SCHEMA_ID[/code]; decode them with that class's [code]decode()[/code]); empty without
## the library or when it gives no such value.
func read(value_id: int) -> PackedByteArray:
	return _backend.renderer_read(_mode, value_id) if is_available() else PackedByteArray()


## The bytes of its settings, a value of its own schema (decode them with that class's
## [code]decode()[/code], as [HapticsMovement.get_settings] does); empty without the library.
func settings_bytes() -> PackedByteArray:
	return _backend.renderer_settings(_mode) if is_available() else PackedByteArray()


## Hands it [param settings] whole, a value of its own settings schema; refused ones are
## reported, naming the field, and change nothing.
func apply_settings(settings: HapticsValue) -> bool:
	if not is_available():
		return false
	var accepted: bool = _backend.set_renderer_settings(_mode, settings)
	changed.emit()
	return accepted
