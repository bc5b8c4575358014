extends Node
## Autoload that owns the native [code]HapticsServer[/code].
##
## The game works without the extension: when the native library is missing or failed to
## load, [method is_available] is false, a warning is printed once, and every query
## returns an empty answer instead of failing to parse or crash.

## Class name the extension registers.
const SERVER_CLASS := &"HapticsServer"

## The native server, or [code]null[/code] when the extension is not loaded. Typed as
## [RefCounted] so that this script parses even without the extension.
var server: RefCounted = null


func _init() -> void:
	if ClassDB.class_exists(SERVER_CLASS):
		server = ClassDB.instantiate(SERVER_CLASS)
	else:
		push_warning(
			(
				"Haptics extension not loaded: playing without force feedback. "
				+ "Build it with 'make build' (see README)."
			)
		)


## True when the native extension is loaded and its server exists.
func is_available() -> bool:
	return server != null


## Every device present (the simulated one first), each a [Dictionary]; empty without the
## extension.
func list_devices() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if server == null:
		return out
	var entries: Array = server.call(&"list_devices")
	out.assign(entries)
	return out


## The extension's version line, or an explanation of why there is none.
func get_version() -> String:
	if server == null:
		return "haptics extension not loaded"
	return str(server.call(&"get_version"))
