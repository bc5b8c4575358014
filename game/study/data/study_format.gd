class_name StudyFormat
extends RefCounted
## The maze study's data format ([code]tools/analysis/FORMAT.md[/code]) as the game uses
## it. The conditions, the criteria, the rating range, the demographics, the file names and
## the CSV columns come from the schema [constant SCHEMA_PATH], which the analysis tool
## reads too; how numbers and timestamps are written is defined here.
##
## Everything here is static; the study runner, the resume scanner and the tests share it.

## The format's one machine-readable description.
const SCHEMA_PATH: String = "res://assets/study/study_schema.json"

static var _schema: Dictionary = _load_schema()
static var _regexes: Dictionary[String, RegEx] = {}

## Written into participant.json; the analysis refuses other versions.
static var format_version: int = _schema.get("format_version", 0)
## The three conditions, in the paper's order.
static var conditions: PackedStringArray = _ids("conditions", "id")
## The ways of ordering the conditions: [code]random[/code], [code]latin_square[/code].
static var counterbalancing_modes: PackedStringArray = _strings(_schema.get("counterbalancing"))
## The movement renderer's contact models a trial may record (the names of
## [code]force_model.contact_model[/code]: [code]per_contact[/code], [code]paper_sum[/code]).
static var contact_models: PackedStringArray = _strings(_schema.get("contact_models"))
## The six criteria (CSV column names), in the paper's Table I order.
static var criteria: PackedStringArray = _ids("criteria", "id")
## Lowest and highest rating.
static var rating_min: int = _section("rating").get("min", 0)
static var rating_max: int = _section("rating").get("max", 0)
## File names inside a participant folder.
static var participant_file: String = _section("files").get("participant", "")
static var trials_file: String = _section("files").get("trials", "")
static var ratings_file: String = _section("files").get("ratings", "")
static var final_file: String = _section("files").get("final", "")
## Folder of the per-trial telemetry files.
static var telemetry_dir: String = str(_section("files").get("telemetry", "")).get_base_dir()
## Subfolders of a study folder that are not participants.
static var reserved_folders: PackedStringArray = _strings(_section("files").get("reserved_folders"))
## The lowest effective sample rate a telemetry file should have, Hz.
static var telemetry_min_rate_hz: float = _schema.get("telemetry_min_rate_hz", 0.0)
## The longest time between two telemetry rows that contact_time_s counts (a longer gap,
## samples lost, counts this much).
static var metric_max_row_step_s: float = _schema.get("metric_max_row_step_s", 0.0)
static var ratings_columns: PackedStringArray = _names(columns("ratings"))
static var trials_columns: PackedStringArray = _names(columns("trials"))
static var telemetry_columns: PackedStringArray = _names(columns("telemetry"))


## The columns of the CSV table [param table] ([code]ratings[/code], [code]trials[/code] or
## [code]telemetry[/code]) in file order, each a dictionary with [code]name[/code],
## [code]type[/code] and, for numbers, [code]min[/code] and [code]max[/code] when bounded.
static func columns(table: String) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	for column: Dictionary in _dictionaries(_section("tables").get(table)):
		if not column.has("each"):
			out.append(column)
			continue
		for name: String in _ids(str(column["each"]), "id"):
			var copy: Dictionary = column.duplicate()
			copy.erase("each")
			copy["name"] = name
			out.append(copy)
	return out


## Why [param value] is not a valid field of [param column] (one of [method columns]), e.g.
## "is not an integer 1-10"; empty when it is valid. A telemetry file name is only checked
## against its trial by the caller.
static func field_problem(column: Dictionary, value: String) -> String:
	var type: String = str(column.get("type", ""))
	match type:
		"id":
			return "" if is_valid_id(value) else "is not a valid participant id"
		"level":
			return "" if is_valid_level(value) else "is not a valid level id"
		"condition":
			return "" if value in conditions else "is unknown"
		"contact_model":
			if value.is_empty() or value in contact_models:
				return ""
			return "is not empty or one of %s" % ", ".join(contact_models)
		"timestamp":
			return "" if is_timestamp(value) else "is not a timestamp"
		"rating":
			return _range_problem(true, value, rating_min, rating_max)
		"integer", "number":
			var low: float = column.get("min", -INF)
			var high: float = column.get("max", INF)
			return _range_problem(type == "integer", value, low, high)
	return ""


## The demographic fields, in display order.
static func demographic_keys() -> PackedStringArray:
	return _ids("demographics", "key")


## The allowed values of the demographic field [param key], in display order.
static func demographic_values(key: String) -> PackedStringArray:
	return _strings(_demographic(key).get("values"))


## The label of the demographic field [param key] on the start screen.
static func demographic_title(key: String) -> String:
	return str(_demographic(key).get("title", key))


## A demographic value as shown on the start screen ("non_binary" is "Non-binary").
static func value_label(value: String) -> String:
	return str(_section("value_labels").get(value, value))


## The title of [param criterion] ("Realism").
static func criterion_title(criterion: String) -> String:
	return str(_criterion(criterion).get("title", criterion))


## The question of [param criterion] as asked on screen: the paper's wording, capitalised,
## with a question mark ("How realistic is the control scheme?").
static func criterion_question(criterion: String) -> String:
	var wording: String = str(_criterion(criterion).get("wording", ""))
	return wording.left(1).to_upper() + wording.substr(1) + "?"


## Whether [param condition] is position control (the constraint renderer); the others are
## acceleration control.
static func is_position_control(condition: String) -> bool:
	return condition == "constraint"


## Whether [param id] is a valid participant id ([code][A-Za-z0-9][A-Za-z0-9_-]*[/code]).
static func is_valid_id(id: String) -> bool:
	return _matches("id", id)


static func is_valid_level(level: String) -> bool:
	return _matches("level", level)


## Whether [param text] is a CSV integer (optional sign and digits).
static func is_integer(text: String) -> bool:
	return _matches("integer", text)


## Whether [param text] is a CSV number (decimal, optional exponent; no nan/inf).
static func is_number(text: String) -> bool:
	return _matches("number", text)


## Whether [param text] is an RFC 3339 timestamp with a time zone.
static func is_timestamp(text: String) -> bool:
	return _matches("timestamp", text)


## [param unix_seconds] (default: now) as an RFC 3339 UTC timestamp with milliseconds,
## e.g. [code]2025-05-01T10:31:07.123Z[/code].
static func timestamp(unix_seconds: float = -1.0) -> String:
	var now: float = unix_seconds if unix_seconds >= 0.0 else Time.get_unix_time_from_system()
	var whole: int = floori(now)
	var millis: int = clampi(floori((now - whole) * 1000.0), 0, 999)
	return "%s.%03dZ" % [Time.get_datetime_string_from_unix_time(whole), millis]


## [param value] as a CSV number with at most [param decimals] decimals: finite (non-finite
## values become 0), never [code]-0[/code], trailing zeros dropped.
static func number(value: float, decimals: int = 3) -> String:
	if not is_finite(value):
		return "0"
	var text: String = String.num(value, decimals)
	return "0" if text.to_float() == 0.0 else text


## One CSV record: the fields joined by commas, terminated by a newline. Fields must not
## contain commas, quotes or line breaks (see [method is_csv_safe]).
static func csv_line(fields: PackedStringArray) -> String:
	return ",".join(fields) + "\n"


## Whether [param field] may be written into a CSV field unquoted.
static func is_csv_safe(field: String) -> bool:
	return not (field.contains(",") or field.contains('"') or field.contains("\n"))


## The telemetry file of a trial, relative to the participant folder.
static func telemetry_name(condition: String, trial_index: int) -> String:
	var pattern: String = str(_section("files").get("telemetry", ""))
	return pattern.format({"condition": condition, "trial_index": trial_index})


# "is not an integer 1-10" (or "a number", or ">= 0" when only the low bound is finite)
# when text is not such a value within the bounds, else "".
static func _range_problem(whole: bool, text: String, low: float, high: float) -> String:
	var bounds: String = ""
	if is_finite(low) and is_finite(high):
		bounds = " %s-%s" % [_bound(low), _bound(high)]
	elif is_finite(low):
		bounds = " >= %s" % _bound(low)
	var valid: bool = is_integer(text) if whole else is_number(text)
	if valid and text.to_float() >= low and text.to_float() <= high:
		return ""
	return "is not %s%s" % ["an integer" if whole else "a number", bounds]


static func _bound(value: float) -> String:
	return str(int(value)) if value == floorf(value) else str(value)


static func _load_schema() -> Dictionary:
	var parsed: Variant = JSON.parse_string(FileAccess.get_file_as_string(SCHEMA_PATH))
	if parsed is Dictionary:
		return parsed
	push_error("The study's data schema %s is missing or not a JSON object." % SCHEMA_PATH)
	return {}


static func _section(key: String) -> Dictionary:
	var value: Variant = _schema.get(key)
	if value is Dictionary:
		return value
	return {}


static func _demographic(key: String) -> Dictionary:
	for entry: Dictionary in _dictionaries(_schema.get("demographics")):
		if entry.get("key") == key:
			return entry
	return {}


static func _criterion(criterion: String) -> Dictionary:
	for entry: Dictionary in _dictionaries(_schema.get("criteria")):
		if entry.get("id") == criterion:
			return entry
	return {}


# The field [param field] of each entry of the schema's list [param key].
static func _ids(key: String, field: String) -> PackedStringArray:
	var out: PackedStringArray = PackedStringArray()
	for entry: Dictionary in _dictionaries(_schema.get(key)):
		out.append(str(entry.get(field, "")))
	return out


static func _names(table_columns: Array[Dictionary]) -> PackedStringArray:
	var out: PackedStringArray = PackedStringArray()
	for column: Dictionary in table_columns:
		out.append(str(column.get("name", "")))
	return out


static func _dictionaries(value: Variant) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if value is Array:
		for item: Variant in value:
			if item is Dictionary:
				out.append(item)
	return out


static func _strings(value: Variant) -> PackedStringArray:
	var out: PackedStringArray = PackedStringArray()
	if value is Array:
		for item: Variant in value:
			out.append(str(item))
	return out


static func _matches(pattern: String, text: String) -> bool:
	if not _regexes.has(pattern):
		var source: String = str(_section("patterns").get(pattern, "$^"))
		_regexes[pattern] = RegEx.create_from_string(source)
	return _regexes[pattern].search(text) != null
