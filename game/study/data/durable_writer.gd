class_name DurableWriter
extends RefCounted
## Writes that are on the disk when they return (an fsync'd append, an atomic whole-file
## write), for the study's records. [method open] gives the native library's
## ([code]DurableFile[/code], reached through [code]durable_native_writer.gd[/code], the one
## script that names it, so this one parses without the library); this base is what a game
## without the library gets: every write fails. Paths are native paths
## ([code]ProjectSettings.globalize_path()[/code]).

## The class the native library registers.
const NATIVE_CLASS: StringName = &"DurableFile"
const NATIVE_WRITER_PATH := "res://game/study/data/durable_native_writer.gd"


## The native writer when the library is loaded, else this base (every write fails).
static func open() -> DurableWriter:
	if is_available():
		return (load(NATIVE_WRITER_PATH) as GDScript).new()
	return DurableWriter.new()


## Whether the native class is there (the haptics extension is loaded).
static func is_available() -> bool:
	return ClassDB.class_exists(NATIVE_CLASS)


## Appends [param _text] (one whole record) and flushes it to the disk.
func append(_path: String, _text: String) -> bool:
	return false


## Writes the whole file atomically; an existing file is refused unless [param _replace].
func write(_path: String, _text: String, _replace: bool) -> bool:
	return false


## Creates the folder and its missing parents.
func make_dirs(_path: String) -> bool:
	return false


## 1 when every line ends with a line break, 0 when the last record was cut short, -1 when
## the file cannot be read (or there is no extension).
func check_complete(_path: String) -> int:
	return -1
