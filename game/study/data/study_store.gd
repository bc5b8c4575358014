class_name StudyStore
extends RefCounted
## Writes one participant's study data so that nothing is ever lost or overwritten
## (format: [code]tools/analysis/FORMAT.md[/code], constants in [StudyFormat]).
##
## Every record is appended in one write followed by fsync through the native
## [code]DurableFile[/code] class ([DurableWriter]): a crash or kill at any moment loses at
## most the trial in progress. A CSV file is created with its header in the same write as
## its first record, so a file never lacks its header. participant.json and final.json are
## written whole (temporary file, fsync, rename); only participant.json is ever replaced,
## once, to set [code]finished[/code]. Methods return [code]false[/code] on failure and
## leave the reason in [member last_error] (the engine has printed the native error too).

## Study folder holding one folder per participant (user:// or an absolute path).
var root: String = ""
## The participant whose folder this store writes.
var participant_id: String = ""
## Why the last write failed; empty after a success.
var last_error: String = ""

var _durable: DurableWriter = DurableWriter.open()


func _init(p_root: String = "", p_participant_id: String = "") -> void:
	root = p_root
	participant_id = p_participant_id


## Whether the native durable writer is there. Without it the study must not start.
static func is_available() -> bool:
	return DurableWriter.is_available()


## The native path of [param path] (user:// and res:// are globalised; absolute paths stay).
static func native_path(path: String) -> String:
	return ProjectSettings.globalize_path(path)


## Ids of the participant folders under [param study_root] that hold a participant.json,
## sorted (the analysis' rules: not a reserved folder, not starting with "." or "_").
static func participant_ids(study_root: String) -> PackedStringArray:
	var ids: PackedStringArray = PackedStringArray()
	var dir: DirAccess = DirAccess.open(study_root)
	if dir == null:
		return ids
	for entry: String in dir.get_directories():
		if (
			entry in StudyFormat.reserved_folders
			or entry.begins_with(".")
			or entry.begins_with("_")
		):
			continue
		if FileAccess.file_exists(
			study_root.path_join(entry).path_join(StudyFormat.participant_file)
		):
			ids.append(entry)
	ids.sort()
	return ids


## The participant's folder.
func folder() -> String:
	return root.path_join(participant_id)


## [param relative] (e.g. [code]trials.csv[/code]) inside the participant's folder.
func path_of(relative: String) -> String:
	return folder().path_join(relative)


## Whether the participant's folder exists and holds anything: such an id is refused for a
## new session (it may only be resumed).
func has_data() -> bool:
	var dir: DirAccess = DirAccess.open(folder())
	if dir == null:
		return false
	dir.include_hidden = true
	return not (dir.get_files().is_empty() and dir.get_directories().is_empty())


## Creates the folder and writes participant.json from [param meta] (refused if it exists).
func create(meta: Dictionary) -> bool:
	if not _durable.make_dirs(native_path(path_of(StudyFormat.telemetry_dir))):
		return _failed("cannot create the folder %s" % folder())
	return _write_json(StudyFormat.participant_file, meta, false)


## Replaces participant.json with [param meta] (used once, to set [code]finished[/code]).
func replace_participant(meta: Dictionary) -> bool:
	return _write_json(StudyFormat.participant_file, meta, true)


## Writes final.json (refused if it exists).
func write_final(favourite: PackedStringArray, differences_text: String) -> bool:
	var data: Dictionary = {
		"participant_id": participant_id,
		"favourite": Array(favourite),
		"differences_text": differences_text,
		"timestamp": StudyFormat.timestamp(),
	}
	return _write_json(StudyFormat.final_file, data, false)


## Appends one ratings.csv record: [param ratings] maps each of [member StudyFormat.criteria]
## to an integer 1–10.
func append_rating(condition: String, order_index: int, ratings: Dictionary) -> bool:
	var fields: PackedStringArray = [participant_id, condition, str(order_index)]
	for criterion: String in StudyFormat.criteria:
		var value: int = ratings.get(criterion, 0)
		if value < StudyFormat.rating_min or value > StudyFormat.rating_max:
			return _failed(
				(
					"rating %s=%d is outside %d..%d"
					% [criterion, value, StudyFormat.rating_min, StudyFormat.rating_max]
				)
			)
		fields.append(str(value))
	fields.append(StudyFormat.timestamp())
	return _append_record(StudyFormat.ratings_file, StudyFormat.ratings_columns, fields)


## Appends one trials.csv record built from [param result] (a [TrialResult]).
func append_trial(result: TrialResult) -> bool:
	var fields: PackedStringArray = [
		participant_id,
		result.condition,
		result.level,
		str(result.trial_index),
		result.contact_model,
		StudyFormat.number(result.time_s, 3),
		"1" if result.completed else "0",
		str(result.wall_collisions),
		StudyFormat.number(result.contact_time_s, 3),
		StudyFormat.number(result.path_length_px, 1),
		StudyFormat.number(result.mean_force_n, 4),
		StudyFormat.number(result.max_force_n, 4),
		result.telemetry_file,
		StudyFormat.timestamp(),
	]
	return _append_record(StudyFormat.trials_file, StudyFormat.trials_columns, fields)


## Appends [param text] (complete lines) to the telemetry file [param relative], writing the
## header first when the file is new.
func append_telemetry(relative: String, text: String) -> bool:
	var path: String = path_of(relative)
	if not FileAccess.file_exists(path):
		text = StudyFormat.csv_line(StudyFormat.telemetry_columns) + text
	if text.is_empty():
		return true
	if not _durable.append(native_path(path), text):
		return _failed("cannot append to %s" % path)
	last_error = ""
	return true


## 1 when every line of [param relative] ends with a newline, 0 when the last record is
## cut short, -1 when it cannot be read.
func check_complete(relative: String) -> int:
	return _durable.check_complete(native_path(path_of(relative)))


func _append_record(
	relative: String, columns: PackedStringArray, fields: PackedStringArray
) -> bool:
	for field: String in fields:
		if not StudyFormat.is_csv_safe(field):
			return _failed(
				"field '%s' of %s holds a comma, quote or line break" % [field, relative]
			)
	var path: String = path_of(relative)
	var text: String = StudyFormat.csv_line(fields)
	if not FileAccess.file_exists(path):
		text = StudyFormat.csv_line(columns) + text
	if not _durable.append(native_path(path), text):
		return _failed("cannot append to %s" % path)
	last_error = ""
	return true


func _write_json(relative: String, data: Dictionary, replace: bool) -> bool:
	var path: String = path_of(relative)
	if not replace and FileAccess.file_exists(path):
		return _failed("%s exists and is never overwritten" % path)
	var text: String = JSON.stringify(json_ready(data), "  ", false) + "\n"
	if not _durable.write(native_path(path), text, replace):
		return _failed("cannot write %s" % path)
	last_error = ""
	return true


func _failed(message: String) -> bool:
	last_error = message
	if not is_available():
		last_error += " (the DurableFile class is missing: haptics extension not loaded)"
	return false


## [param value] with every integral float turned into an int, recursively. Godot's JSON
## parser reads every number as a float, so a record read back on resume would otherwise
## be rewritten with "seed": 12345.0, which FORMAT.md's integer fields do not allow.
static func json_ready(value: Variant) -> Variant:
	if value is Dictionary:
		var out: Dictionary = {}
		var source: Dictionary = value
		for key: Variant in source:
			out[key] = json_ready(source[key])
		return out
	if value is Array:
		var items: Array = []
		var source_items: Array = value
		for item: Variant in source_items:
			items.append(json_ready(item))
		return items
	if value is float:
		var number: float = value
		if is_finite(number) and number == floorf(number) and absf(number) < 9.0e15:
			return int(number)
	return value
