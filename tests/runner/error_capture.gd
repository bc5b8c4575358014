extends Logger
## Collects the engine and script errors logged while tests run.
##
## The runner installs one instance with [method OS.add_logger]. The engine may call
## [method _log_error] from any thread, so entries are formatted at once and kept behind a
## [Mutex]; the runner drains them on the main thread at the end of each test phase.
## Nothing here prints: printing from a logger callback would re-enter the logger.


## One logged error or warning.
class Entry:
	extends RefCounted

	## A [enum Logger.ErrorType] value.
	var error_type: int = Logger.ERROR_TYPE_ERROR
	## The message as the engine prints it (the rationale when given, else the code).
	var text: String = ""
	## The condition or message the engine reported (push_error's message lands here).
	var code: String = ""
	## The explanation given by the engine, often empty.
	var rationale: String = ""
	## "file:line" of the innermost script frame when known, else of the engine source.
	var location: String = ""

	## True for warnings (push_warning, WARN_PRINT): they never fail a test on their own.
	func is_warning() -> bool:
		return error_type == Logger.ERROR_TYPE_WARNING

	## True if [param needle] occurs in the code, rationale or printed text.
	func matches(needle: String) -> bool:
		return code.contains(needle) or rationale.contains(needle) or text.contains(needle)

	## A one-line description such as [code]SCRIPT ERROR: Cannot call ... (res://a.gd:3)[/code].
	func describe() -> String:
		var kind: String = "ERROR"
		match error_type:
			Logger.ERROR_TYPE_WARNING:
				kind = "WARNING"
			Logger.ERROR_TYPE_SCRIPT:
				kind = "SCRIPT ERROR"
			Logger.ERROR_TYPE_SHADER:
				kind = "SHADER ERROR"
		var one_line: String = text.strip_edges().replace("\n", " ")
		if location.is_empty():
			return "%s: %s" % [kind, one_line]
		return "%s: %s (%s)" % [kind, one_line, location]


var _mutex: Mutex = Mutex.new()
var _entries: Array[Entry] = []


## Removes and returns everything logged since the previous call.
func drain() -> Array[Entry]:
	_mutex.lock()
	var taken: Array[Entry] = _entries
	_entries = []
	_mutex.unlock()
	return taken


func _log_error(
	function: String,
	file: String,
	line: int,
	code: String,
	rationale: String,
	_editor_notify: bool,
	error_type: int,
	script_backtraces: Array[ScriptBacktrace]
) -> void:
	var entry: Entry = Entry.new()
	entry.error_type = error_type
	entry.code = code
	entry.rationale = rationale
	entry.text = rationale if not rationale.is_empty() else code
	if file.contains("://"):
		# Script errors (parse errors included) name the script and line themselves.
		entry.location = "%s:%d" % [file, line]
	else:
		# Errors raised in engine code (push_error() too) name a C++ file: prefer the
		# innermost script frame that led there.
		entry.location = "%s:%d in %s()" % [file, line, function]
		for backtrace: ScriptBacktrace in script_backtraces:
			if backtrace != null and backtrace.get_frame_count() > 0:
				entry.location = (
					"%s:%d" % [backtrace.get_frame_file(0), backtrace.get_frame_line(0)]
				)
				break
	_mutex.lock()
	_entries.append(entry)
	_mutex.unlock()
