extends RefCounted
## Shared helpers of the study tests: a fresh study folder under user:// per test (never
## the real study folder), reading CSV files back, and removing folders.

## Parent of every test study folder.
const TEST_ROOT: String = "user://study_tests"
## The tiny maze study settings (short trials).
const TINY_CONFIG: String = "res://tests/study/fixtures/tiny_study.json"


## A new, empty study folder for [param label].
static func fresh_root(label: String) -> String:
	var root: String = TEST_ROOT.path_join("%s_%d" % [label, Time.get_ticks_usec()])
	DirAccess.make_dir_recursive_absolute(root)
	return root


## Deletes [param path] and everything in it (only below [constant TEST_ROOT]).
static func remove_tree(path: String) -> void:
	if not path.begins_with(TEST_ROOT):
		return
	var dir: DirAccess = DirAccess.open(path)
	if dir == null:
		return
	dir.include_hidden = true
	for sub: String in dir.get_directories():
		remove_tree(path.path_join(sub))
	for file: String in dir.get_files():
		DirAccess.remove_absolute(path.path_join(file))
	DirAccess.remove_absolute(path)


## The lines of a text file without the final empty one ([] when missing).
static func lines_of(path: String) -> PackedStringArray:
	if not FileAccess.file_exists(path):
		return PackedStringArray()
	var lines: PackedStringArray = FileAccess.get_file_as_string(path).split("\n")
	if not lines.is_empty() and lines[lines.size() - 1].is_empty():
		lines.remove_at(lines.size() - 1)
	return lines


## The records of a CSV file as dictionaries keyed by the header's columns.
static func records_of(path: String) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var lines: PackedStringArray = lines_of(path)
	if lines.is_empty():
		return out
	var header: PackedStringArray = lines[0].split(",")
	for i: int in range(1, lines.size()):
		var fields: PackedStringArray = lines[i].split(",")
		var record: Dictionary = {}
		for c: int in mini(header.size(), fields.size()):
			record[header[c]] = fields[c]
		out.append(record)
	return out


## A parsed JSON object file ({} when missing or invalid).
static func json_of(path: String) -> Dictionary:
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(path))
	if parsed is Dictionary:
		var data: Dictionary = parsed
		return data
	return {}


## A valid participant.json record (FORMAT.md) for participant [param id].
static func meta(id: String, order: Array = ["none", "movement", "constraint"]) -> Dictionary:
	return {
		"format_version": StudyFormat.format_version,
		"participant_id": id,
		"demographics":
		{
			"age_band": "20-29",
			"gender": "male",
			"handedness": "right",
			"hand_used": "left",
			"gaming_experience": "some",
		},
		"seed": 1,
		"condition_order": order,
		"counterbalancing": "random",
		"app_version": "test",
		"extension_version": "test",
		"started": StudyFormat.timestamp(),
		"finished": null,
	}
