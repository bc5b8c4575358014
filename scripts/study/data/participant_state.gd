class_name ParticipantState
extends RefCounted
## What a participant's folder holds, checked record by record: the basis for resuming an
## interrupted session where it stopped.
##
## [method scan] reads participant.json, ratings.csv, trials.csv, the telemetry files the
## trials reference, and final.json, and checks them against FORMAT.md. Anything wrong (a
## truncated last record, a bad header, an unreadable JSON file, a value out of range, a
## duplicate) is collected in [member problems] as [code]FILE:LINE: what[/code]; a session is
## only resumed when there is none (see [method can_resume]). Harmless leftovers of a crash
## (the telemetry file of the interrupted trial, a participant.json.tmp) are listed in
## [member notes]; the interrupted trial's index is never reused.

## What comes next in the session (see [method next_step]).
enum Step { PRACTICE, TRIALS, RATING, FINAL, FINISH, DONE }

## The participant id (the folder name).
var participant_id: String = ""
## Whether a participant.json was found at all.
var exists: bool = false
## participant.json's content (empty when missing or unreadable).
var meta: Dictionary = {}
## The presentation order from participant.json.
var condition_order: PackedStringArray = PackedStringArray()
## Rated conditions: condition → order_index.
var rated: Dictionary[String, int] = {}
## Trial records per condition.
var trial_counts: Dictionary[String, int] = {}
## Per condition, the next unused trial index (records and telemetry files both count).
var next_index: Dictionary[String, int] = {}
## Whether final.json exists.
var final_written: bool = false
## Corruption found ("FILE:LINE: what"); resuming is refused while there is any.
var problems: PackedStringArray = PackedStringArray()
## Harmless findings (interrupted trial's telemetry, temporary files).
var notes: PackedStringArray = PackedStringArray()

var _store: StudyStore = null
var _row_lines: PackedInt32Array = PackedInt32Array()


## Reads and checks the folder of [param id] under [param study_root].
static func scan(study_root: String, id: String) -> ParticipantState:
	var state: ParticipantState = ParticipantState.new()
	state.participant_id = id
	state._store = StudyStore.new(study_root, id)
	for condition: String in StudyFormat.CONDITIONS:
		state.trial_counts[condition] = 0
		state.next_index[condition] = 0
	state._scan()
	return state


## Whether the session can be resumed: participant.json exists and nothing is corrupt.
func can_resume() -> bool:
	return exists and problems.is_empty()


## Trials still to run for the condition at [param order_index].
func trials_left(order_index: int, trials_per_condition: int) -> int:
	return maxi(0, trials_per_condition - trial_counts[condition_order[order_index]])


## What to do next: [enum Step] and, for TRIALS and RATING, the order index, as
## [code]{"step": Step, "order_index": int}[/code].
func next_step(trials_per_condition: int) -> Dictionary:
	var any_data: bool = not rated.is_empty()
	for condition: String in StudyFormat.CONDITIONS:
		any_data = any_data or next_index[condition] > 0
	if not any_data:
		return {"step": Step.PRACTICE, "order_index": 0}
	for i: int in condition_order.size():
		var condition: String = condition_order[i]
		if rated.has(condition):
			continue
		if trial_counts[condition] < trials_per_condition:
			return {"step": Step.TRIALS, "order_index": i}
		return {"step": Step.RATING, "order_index": i}
	if not final_written:
		return {"step": Step.FINAL, "order_index": -1}
	if meta.get("finished") == null:
		return {"step": Step.FINISH, "order_index": -1}
	return {"step": Step.DONE, "order_index": -1}


## Everything found, one line each (problems first), for the screen and the log.
func report_lines() -> PackedStringArray:
	var lines: PackedStringArray = PackedStringArray()
	for problem: String in problems:
		lines.append(problem)
	for note: String in notes:
		lines.append("note: " + note)
	return lines


func _scan() -> void:
	var folder: String = _store.folder()
	if not DirAccess.dir_exists_absolute(folder):
		return
	_check_participant()
	if not exists:
		return
	_check_ratings()
	_check_trials()
	_check_final()
	_check_leftovers()


func _rel(name: String) -> String:
	return "%s/%s" % [participant_id, name]


func _problem(name: String, line: int, what: String) -> void:
	if line > 0:
		problems.append("%s:%d: %s" % [_rel(name), line, what])
	else:
		problems.append("%s: %s" % [_rel(name), what])


func _check_participant() -> void:
	var name: String = StudyFormat.PARTICIPANT_FILE
	if not FileAccess.file_exists(_store.path_of(name)):
		if _store.has_data():
			_problem(name, 0, "missing (the folder holds data without it)")
		return
	exists = true
	var data: Dictionary = _read_json(name)
	if data.is_empty():
		return
	meta = data
	var version: Variant = data.get("format_version", -1)
	if not StudyFormat.is_integer(str(version)) and typeof(version) != TYPE_FLOAT:
		version = -1
	if str(version).to_int() != StudyFormat.FORMAT_VERSION:
		_problem(name, 0, "'format_version' is not %d" % StudyFormat.FORMAT_VERSION)
	if str(data.get("participant_id", "")) != participant_id:
		_problem(name, 0, "'participant_id' does not match the folder name")
	var order: Array = []
	if data.get("condition_order") is Array:
		order = data["condition_order"]
	var sorted_order: Array = order.duplicate()
	sorted_order.sort()
	var expected: Array = Array(StudyFormat.CONDITIONS)
	expected.sort()
	if sorted_order != expected:
		_problem(name, 0, "'condition_order' is not an ordering of none, movement, constraint")
	else:
		for condition: Variant in order:
			condition_order.append(str(condition))
	var demographics: Variant = data.get("demographics")
	if not demographics is Dictionary:
		_problem(name, 0, "'demographics' is missing")
	else:
		var values: Dictionary = demographics
		for key: String in StudyFormat.demographic_keys():
			if not str(values.get(key, "")) in StudyFormat.demographic_values(key):
				_problem(name, 0, "'demographics.%s' is missing or not an allowed value" % key)
	if typeof(data.get("seed")) != TYPE_FLOAT and typeof(data.get("seed")) != TYPE_INT:
		_problem(name, 0, "'seed' is not an integer")
	if not str(data.get("counterbalancing", "")) in StudyFormat.COUNTERBALANCING:
		_problem(name, 0, "'counterbalancing' is not random or latin_square")
	if not StudyFormat.is_timestamp(str(data.get("started", ""))):
		_problem(name, 0, "'started' is not a timestamp")
	var finished: Variant = data.get("finished", "missing")
	if finished != null and not StudyFormat.is_timestamp(str(finished)):
		_problem(name, 0, "'finished' is neither null nor a timestamp")


func _check_ratings() -> void:
	var name: String = StudyFormat.RATINGS_FILE
	var rows: Array[PackedStringArray] = _read_csv(name, StudyFormat.RATINGS_COLUMNS)
	for i: int in rows.size():
		var row: PackedStringArray = rows[i]
		var line: int = _row_lines[i]
		if not _row_common(name, line, row):
			continue
		var condition: String = row[1]
		if rated.has(condition):
			_problem(name, line, "condition '%s' is rated twice" % condition)
			continue
		if not row[2] in ["0", "1", "2"]:
			_problem(name, line, "order_index '%s' is not 0, 1 or 2" % row[2])
			continue
		var order_index: int = row[2].to_int()
		if condition_order.size() == 3 and condition_order[order_index] != condition:
			_problem(
				name,
				line,
				"order_index %d is not '%s' in condition_order" % [order_index, condition]
			)
			continue
		var ok: bool = true
		for c: int in range(3, 9):
			var value: String = row[c]
			if not StudyFormat.is_integer(value) or value.to_int() < 1 or value.to_int() > 10:
				_problem(
					name,
					line,
					"%s '%s' is not an integer 1-10" % [StudyFormat.RATINGS_COLUMNS[c], value]
				)
				ok = false
		if not StudyFormat.is_timestamp(row[9]):
			_problem(name, line, "timestamp '%s' is not a timestamp" % row[9])
			ok = false
		if ok:
			rated[condition] = order_index


func _check_trials() -> void:
	var name: String = StudyFormat.TRIALS_FILE
	var rows: Array[PackedStringArray] = _read_csv(name, StudyFormat.TRIALS_COLUMNS)
	var seen: Dictionary[String, int] = {}
	for i: int in rows.size():
		var row: PackedStringArray = rows[i]
		var line: int = _row_lines[i]
		if not _row_common(name, line, row):
			continue
		var condition: String = row[1]
		if not StudyFormat.is_valid_level(row[2]):
			_problem(name, line, "level '%s' is not a valid level id" % row[2])
			continue
		if not StudyFormat.is_integer(row[3]) or row[3].to_int() < 0:
			_problem(name, line, "trial_index '%s' is not an integer >= 0" % row[3])
			continue
		var index: int = row[3].to_int()
		var key: String = "%s_%d" % [condition, index]
		if seen.has(key):
			_problem(
				name, line, "trial %s #%d appears twice (line %d)" % [condition, index, seen[key]]
			)
			continue
		seen[key] = line
		if not _trial_values_ok(name, line, row):
			continue
		var telemetry: String = row[11]
		if not telemetry.is_empty():
			if telemetry != StudyFormat.telemetry_name(condition, index):
				_problem(name, line, "telemetry_file '%s' is not the expected name" % telemetry)
				continue
			if not FileAccess.file_exists(_store.path_of(telemetry)):
				_problem(name, line, "telemetry file '%s' does not exist" % telemetry)
				continue
			if _store.check_complete(telemetry) != 1:
				_problem(
					telemetry,
					0,
					"truncated or unreadable (referenced on trials.csv line %d)" % line
				)
				continue
		trial_counts[condition] += 1
		next_index[condition] = maxi(next_index[condition], index + 1)
	_check_telemetry_files(seen)


func _trial_values_ok(name: String, line: int, row: PackedStringArray) -> bool:
	var ok: bool = true
	for c: int in [4, 7, 8, 9, 10]:
		if not StudyFormat.is_number(row[c]) or row[c].to_float() < 0.0:
			_problem(
				name, line, "%s '%s' is not a number >= 0" % [StudyFormat.TRIALS_COLUMNS[c], row[c]]
			)
			ok = false
	if not row[5] in ["0", "1"]:
		_problem(name, line, "completed '%s' is not 0 or 1" % row[5])
		ok = false
	if not StudyFormat.is_integer(row[6]) or row[6].to_int() < 0:
		_problem(name, line, "wall_collisions '%s' is not an integer >= 0" % row[6])
		ok = false
	if not StudyFormat.is_timestamp(row[12]):
		_problem(name, line, "timestamp '%s' is not a timestamp" % row[12])
		ok = false
	return ok


# Telemetry files no record references: the trial a crash interrupted. Their indices are
# used up, so the resumed trial never writes over one.
func _check_telemetry_files(referenced: Dictionary[String, int]) -> void:
	var dir: DirAccess = DirAccess.open(_store.path_of(StudyFormat.TELEMETRY_DIR))
	if dir == null:
		return
	for file: String in dir.get_files():
		var stem: String = file.get_basename()
		var condition: String = stem.get_slice("_", 0)
		var index_text: String = stem.trim_prefix(condition + "_")
		if file.get_extension() != "csv" or not condition in StudyFormat.CONDITIONS:
			notes.append(
				"%s: unexpected file, ignored" % _rel(StudyFormat.TELEMETRY_DIR + "/" + file)
			)
			continue
		if not StudyFormat.is_integer(index_text):
			notes.append(
				"%s: unexpected file, ignored" % _rel(StudyFormat.TELEMETRY_DIR + "/" + file)
			)
			continue
		var index: int = index_text.to_int()
		next_index[condition] = maxi(next_index[condition], index + 1)
		if not referenced.has(stem):
			notes.append(
				(
					"%s: no trials.csv record (an interrupted trial): kept, not reused"
					% _rel(StudyFormat.TELEMETRY_DIR + "/" + file)
				)
			)


func _check_final() -> void:
	var name: String = StudyFormat.FINAL_FILE
	if not FileAccess.file_exists(_store.path_of(name)):
		return
	var data: Dictionary = _read_json(name)
	if data.is_empty():
		return
	final_written = true
	if str(data.get("participant_id", "")) != participant_id:
		_problem(name, 0, "'participant_id' does not match the folder name")
	if not data.get("favourite") is Array:
		_problem(name, 0, "'favourite' is not a list")
	else:
		var favourite: Array = data["favourite"]
		for condition: Variant in favourite:
			if not str(condition) in StudyFormat.CONDITIONS:
				_problem(name, 0, "'favourite' holds an unknown condition")


func _check_leftovers() -> void:
	var dir: DirAccess = DirAccess.open(_store.folder())
	if dir == null:
		return
	var known: PackedStringArray = [
		StudyFormat.PARTICIPANT_FILE,
		StudyFormat.TRIALS_FILE,
		StudyFormat.RATINGS_FILE,
		StudyFormat.FINAL_FILE,
	]
	for file: String in dir.get_files():
		if not file in known:
			notes.append("%s: unexpected file, ignored" % _rel(file))


# Checks shared by both tables: column count, participant id, condition.
func _row_common(name: String, line: int, row: PackedStringArray) -> bool:
	if row[0] != participant_id:
		_problem(name, line, "participant_id '%s' is not '%s'" % [row[0], participant_id])
		return false
	if not row[1] in StudyFormat.CONDITIONS:
		_problem(name, line, "condition '%s' is unknown" % row[1])
		return false
	return true


# The records of a CSV file (header checked and dropped), each with the right number of
# fields, their line numbers in _row_lines; problems are reported. A missing file has none.
func _read_csv(name: String, columns: PackedStringArray) -> Array[PackedStringArray]:
	var rows: Array[PackedStringArray] = []
	_row_lines.clear()
	var path: String = _store.path_of(name)
	if not FileAccess.file_exists(path):
		return rows
	var complete: int = _store.check_complete(name)
	var bytes: PackedByteArray = FileAccess.get_file_as_bytes(path)
	if complete < 0 or (bytes.is_empty() and FileAccess.get_open_error() != OK):
		_problem(name, 0, "cannot be read")
		return rows
	var text: String = bytes.get_string_from_utf8()
	if text.is_empty():
		_problem(name, 1, "empty file (the header row is missing)")
		return rows
	var lines: PackedStringArray = text.split("\n")
	var last: String = lines[lines.size() - 1]
	lines.remove_at(lines.size() - 1)
	if complete == 0 or not last.is_empty():
		var shown: String = last if last.length() <= 60 else last.left(57) + "..."
		_problem(
			name,
			lines.size() + 1,
			"truncated record: the last line has no terminating newline ('%s')" % shown
		)
	if lines.is_empty():
		return rows
	if lines[0].trim_suffix("\r") != ",".join(columns):
		_problem(name, 1, "bad header: expected '%s'" % ",".join(columns))
		return rows
	for i: int in range(1, lines.size()):
		var line: String = lines[i].trim_suffix("\r")
		if line.is_empty():
			_problem(name, i + 1, "empty line")
			continue
		var fields: PackedStringArray = line.split(",")
		if fields.size() != columns.size():
			_problem(name, i + 1, "expected %d columns, found %d" % [columns.size(), fields.size()])
			continue
		rows.append(fields)
		_row_lines.append(i + 1)
	return rows


func _read_json(name: String) -> Dictionary:
	var path: String = _store.path_of(name)
	var text: String = FileAccess.get_file_as_string(path)
	var json: JSON = JSON.new()
	if text.is_empty() or json.parse(text) != OK:
		var line: int = maxi(1, json.get_error_line()) if not text.is_empty() else 1
		_problem(name, line, "not valid JSON (%s)" % json.get_error_message())
		return {}
	if not json.data is Dictionary:
		_problem(name, 1, "not a JSON object")
		return {}
	var data: Dictionary = json.data
	return data
