class_name DurableWriter
extends RefCounted
## Typed access to the native [code]DurableFile[/code] (writes that are on the disk when
## they return: an fsync'd append, an atomic whole-file write), for scripts that must parse
## without the extension. Paths are native paths
## ([code]ProjectSettings.globalize_path()[/code]). Without the extension every write fails.

const NATIVE_CLASS: StringName = &"DurableFile"

var _file: Object = null


func _init() -> void:
	if is_available():
		_file = ClassDB.instantiate(NATIVE_CLASS)


## Whether the native class is there (the haptics extension is loaded and new enough).
static func is_available() -> bool:
	if not ClassDB.class_exists(NATIVE_CLASS):
		return false
	for method: StringName in [&"append", &"write", &"make_dirs", &"check_complete"]:
		if not ClassDB.class_has_method(NATIVE_CLASS, method):
			return false
	return true


## Appends [param text] (one whole record) and flushes it to the disk.
func append(path: String, text: String) -> bool:
	return _file != null and _file.call(&"append", path, text)


## Writes the whole file atomically; an existing file is refused unless [param replace].
func write(path: String, text: String, replace: bool) -> bool:
	return _file != null and _file.call(&"write", path, text, replace)


## Creates the folder and its missing parents.
func make_dirs(path: String) -> bool:
	return _file != null and _file.call(&"make_dirs", path)


## 1 when every line ends with a line break, 0 when the last record was cut short, -1 when
## the file cannot be read (or there is no extension).
func check_complete(path: String) -> int:
	return _file.call(&"check_complete", path) if _file != null else -1
