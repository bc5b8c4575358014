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


## Reads and checks the folder of [param id] under [param study_root].
static func scan(study_root: String, id: String) -> ParticipantState:
	var state: ParticipantState = ParticipantState.new()
	state.participant_id = id
	state._store = StudyStore.new(study_root, id)
	for condition: String in StudyFormat.conditions:
		state.trial_counts[condition] = 0
		state.next_index[condition] = 0
	state._scan()
	return state


## Whether the session can be resumed: participant.json exists and nothing is corrupt.
func can_resume() -> bool:
	return exists and problems.is_empty()


## What to do next: [enum Step] and, for TRIALS and RATING, the order index, as
## [code]{"step": Step, "order_index": int}[/code].
func next_step(trials_per_condition: int) -> Dictionary:
	var any_data: bool = not rated.is_empty()
	for condition: String in StudyFormat.conditions:
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
	var name: String = StudyFormat.participant_file
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
	if str(version).to_int() != StudyFormat.format_version:
		_problem(name, 0, "'format_version' is not %d" % StudyFormat.format_version)
	if str(data.get("participant_id", "")) != participant_id:
		_problem(name, 0, "'participant_id' does not match the folder name")
	var order: Array = []
	if data.get("condition_order") is Array:
		order = data["condition_order"]
	var sorted_order: Array = order.duplicate()
	sorted_order.sort()
	var expected: Array = Array(StudyFormat.conditions)
	expected.sort()
	if sorted_order != expected:
		var conditions: String = ", ".join(StudyFormat.conditions)
		_problem(name, 0, "'condition_order' is not an ordering of %s" % conditions)
	else:
		for condition: Variant in order:
			condition_order.append(str(condition))
	_check_demographics(name, data.get("demographics"))
	if typeof(data.get("seed")) != TYPE_FLOAT and typeof(data.get("seed")) != TYPE_INT:
		_problem(name, 0, "'seed' is not an integer")
	var modes: PackedStringArray = StudyFormat.counterbalancing_modes
	if not str(data.get("counterbalancing", "")) in modes:
		_problem(name, 0, "'counterbalancing' is not %s" % " or ".join(modes))
	if not StudyFormat.is_timestamp(str(data.get("started", ""))):
		_problem(name, 0, "'started' is not a timestamp")
	var finished: Variant = data.get("finished", "missing")
	if finished != null and not StudyFormat.is_timestamp(str(finished)):
		_problem(name, 0, "'finished' is neither null nor a timestamp")


func _check_demographics(name: String, demographics: Variant) -> void:
	if not demographics is Dictionary:
		_problem(name, 0, "'demographics' is missing")
		return
	var values: Dictionary = demographics
	for key: String in StudyFormat.demographic_keys():
		if not str(values.get(key, "")) in StudyFormat.demographic_values(key):
			_problem(name, 0, "'demographics.%s' is missing or not an allowed value" % key)


func _check_ratings() -> void:
	var name: String = StudyFormat.ratings_file
	var rows: Dictionary[int, Dictionary] = _read_csv(name, StudyFormat.columns("ratings"))
	for line: int in rows:
		var row: Dictionary = rows[line]
		if not _is_own(name, line, row):
			continue
		var condition: String = row["condition"]
		if rated.has(condition):
			_problem(name, line, "condition '%s' is rated twice" % condition)
			continue
		var order_index: int = str(row["order_index"]).to_int()
		if order_index < condition_order.size() and condition_order[order_index] != condition:
			_problem(
				name,
				line,
				"order_index %d is not '%s' in condition_order" % [order_index, condition]
			)
			continue
		rated[condition] = order_index


func _check_trials() -> void:
	var name: String = StudyFormat.trials_file
	var rows: Dictionary[int, Dictionary] = _read_csv(name, StudyFormat.columns("trials"))
	var seen: Dictionary[String, int] = {}
	for line: int in rows:
		var row: Dictionary = rows[line]
		if not _is_own(name, line, row):
			continue
		var condition: String = row["condition"]
		var index: int = str(row["trial_index"]).to_int()
		var key: String = "%s_%d" % [condition, index]
		if seen.has(key):
			_problem(
				name, line, "trial %s #%d appears twice (line %d)" % [condition, index, seen[key]]
			)
			continue
		seen[key] = line
		var telemetry: String = row["telemetry_file"]
		if not telemetry.is_empty() and not _telemetry_ok(name, line, telemetry, condition, index):
			continue
		trial_counts[condition] += 1
		next_index[condition] = maxi(next_index[condition], index + 1)
	_check_telemetry_files(seen)


# Whether the telemetry file a trials.csv record names is the trial's and complete.
func _telemetry_ok(
	name: String, line: int, telemetry: String, condition: String, index: int
) -> bool:
	if telemetry != StudyFormat.telemetry_name(condition, index):
		_problem(name, line, "telemetry_file '%s' is not the expected name" % telemetry)
		return false
	if not FileAccess.file_exists(_store.path_of(telemetry)):
		_problem(name, line, "telemetry file '%s' does not exist" % telemetry)
		return false
	if _store.check_complete(telemetry) != 1:
		_problem(telemetry, 0, "truncated or unreadable (referenced on trials.csv line %d)" % line)
		return false
	return true


# Telemetry files no record references: the trial a crash interrupted. Their indices are
# used up, so the resumed trial never writes over one.
func _check_telemetry_files(referenced: Dictionary[String, int]) -> void:
	var dir: DirAccess = DirAccess.open(_store.path_of(StudyFormat.telemetry_dir))
	if dir == null:
		return
	for file: String in dir.get_files():
		var rel: String = _rel(StudyFormat.telemetry_dir.path_join(file))
		var stem: String = file.get_basename()
		var condition: String = stem.get_slice("_", 0)
		var index_text: String = stem.trim_prefix(condition + "_")
		var known: bool = file.get_extension() == "csv" and condition in StudyFormat.conditions
		if not known or not StudyFormat.is_integer(index_text):
			notes.append("%s: unexpected file, ignored" % rel)
			continue
		var index: int = index_text.to_int()
		next_index[condition] = maxi(next_index[condition], index + 1)
		if not referenced.has(stem):
			notes.append("%s: no trials.csv record (an interrupted trial): kept, not reused" % rel)


func _check_final() -> void:
	var name: String = StudyFormat.final_file
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
			if not str(condition) in StudyFormat.conditions:
				_problem(name, 0, "'favourite' holds an unknown condition")


func _check_leftovers() -> void:
	var dir: DirAccess = DirAccess.open(_store.folder())
	if dir == null:
		return
	var known: PackedStringArray = [
		StudyFormat.participant_file,
		StudyFormat.trials_file,
		StudyFormat.ratings_file,
		StudyFormat.final_file,
	]
	for file: String in dir.get_files():
		if not file in known:
			notes.append("%s: unexpected file, ignored" % _rel(file))


# Whether a record is this participant's (its fields are valid already).
func _is_own(name: String, line: int, row: Dictionary) -> bool:
	if row["participant_id"] == participant_id:
		return true
	_problem(
		name, line, "participant_id '%s' is not '%s'" % [row["participant_id"], participant_id]
	)
	return false


# The valid records of a CSV file by line number, each a dictionary column → field (the
# header is checked against [param columns]); every problem is reported. A missing file
# has none.
func _read_csv(name: String, columns: Array[Dictionary]) -> Dictionary[int, Dictionary]:
	var rows: Dictionary[int, Dictionary] = {}
	var records: Array[PackedStringArray] = _csv_records(name)
	if records.is_empty():
		return rows
	var names: PackedStringArray = PackedStringArray()
	for column: Dictionary in columns:
		names.append(str(column["name"]))
	if records[0] != names:
		_problem(name, 1, "bad header: expected '%s'" % ",".join(names))
		return rows
	for i: int in range(1, records.size()):
		var fields: PackedStringArray = records[i]
		var line: int = i + 1
		if fields.size() == 1 and fields[0].is_empty():
			_problem(name, line, "empty line")
		elif fields.size() != columns.size():
			_problem(name, line, "expected %d columns, found %d" % [columns.size(), fields.size()])
		else:
			var row: Dictionary = {}
			var ok: bool = true
			for c: int in columns.size():
				var problem: String = StudyFormat.field_problem(columns[c], fields[c])
				if not problem.is_empty():
					_problem(name, line, "%s '%s' %s" % [names[c], fields[c], problem])
					ok = false
				row[names[c]] = fields[c]
			if ok:
				rows[line] = row
	return rows


# The complete records of a CSV file (header first; [] when missing or unusable). A cut-off
# last record and quotes (the format has none) are reported.
func _csv_records(name: String) -> Array[PackedStringArray]:
	var records: Array[PackedStringArray] = []
	var path: String = _store.path_of(name)
	if not FileAccess.file_exists(path):
		return records
	var complete: int = _store.check_complete(name)
	var file: FileAccess = FileAccess.open(path, FileAccess.READ)
	if complete < 0 or file == null:
		_problem(name, 0, "cannot be read")
		return records
	var text: String = file.get_as_text()
	if text.is_empty():
		_problem(name, 1, "empty file (the header row is missing)")
		return records
	if text.contains('"'):
		_problem(name, text.left(text.find('"')).count("\n") + 1, 'holds a quote (")')
		return records
	file.seek(0)
	while file.get_position() < file.get_length():
		records.append(file.get_csv_line())
	if complete == 0 or not text.ends_with("\n"):
		var last_fields: PackedStringArray = records.pop_back()
		var last: String = ",".join(last_fields)
		var shown: String = last if last.length() <= 60 else last.left(57) + "..."
		_problem(
			name,
			records.size() + 1,
			"truncated record: the last line has no terminating newline ('%s')" % shown
		)
	return records


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
