class_name StudyFormat
extends RefCounted
## The maze study's data format, version 1 ([code]tools/analysis/FORMAT.md[/code]): file
## names, CSV columns, the value lists of the demographics, the six criteria with the
## paper's wording, and how numbers and timestamps are written.
##
## Everything here is static; the study runner, the resume scanner and the tests share it
## so the format is spelled out once.

## Written into participant.json; the analysis refuses other versions.
const FORMAT_VERSION: int = 1
## The three conditions, in the paper's order.
const CONDITIONS: PackedStringArray = ["none", "movement", "constraint"]
## Counterbalancing modes.
const COUNTERBALANCING: PackedStringArray = ["random", "latin_square"]
## The six criteria (CSV column names), in the paper's Table I order.
const CRITERIA: PackedStringArray = [
	"realism", "ease", "aptness", "intuitiveness", "enthusiasm", "partiality"
]
## Each criterion's title and question as shown to participants (the paper's wording);
## read it through [method criterion_title] and [method criterion_question].
const CRITERION_TEXT: Dictionary = {
	"realism": ["Realism", "How realistic is the control scheme?"],
	"ease": ["Ease", "How easy is it to control the character?"],
	"aptness": ["Aptness", "How appropriate does the control feel?"],
	"intuitiveness": ["Intuitiveness", "How natural is the control?"],
	"enthusiasm": ["Enthusiasm", "How much did you enjoy this method?"],
	"partiality": ["Partiality", "How much do you prefer this method?"],
}
## Lowest and highest rating.
const RATING_MIN: int = 1
## See [constant RATING_MIN].
const RATING_MAX: int = 10
## Demographic fields in participant.json and their allowed values, in display order
## (read the values through [method demographic_values]).
const DEMOGRAPHICS: Dictionary = {
	"age_band": ["under_20", "20-29", "30-39", "40-49", "50-59", "60+", "undisclosed"],
	"gender": ["female", "male", "non_binary", "other", "undisclosed"],
	"handedness": ["left", "right", "ambidextrous", "undisclosed"],
	"hand_used": ["left", "right"],
	"gaming_experience": ["none", "little", "some", "extensive"],
}
## Labels of the demographic fields on the start screen.
const DEMOGRAPHIC_TITLES: Dictionary = {
	"age_band": "Age",
	"gender": "Gender",
	"handedness": "Handedness",
	"hand_used": "Hand on the device",
	"gaming_experience": "Gaming experience",
}

## File names inside a participant folder.
const PARTICIPANT_FILE: String = "participant.json"
## See [constant PARTICIPANT_FILE].
const TRIALS_FILE: String = "trials.csv"
## See [constant PARTICIPANT_FILE].
const RATINGS_FILE: String = "ratings.csv"
## See [constant PARTICIPANT_FILE].
const FINAL_FILE: String = "final.json"
## Folder of the per-trial telemetry files.
const TELEMETRY_DIR: String = "telemetry"

## Columns of ratings.csv.
const RATINGS_COLUMNS: PackedStringArray = [
	"participant_id",
	"condition",
	"order_index",
	"realism",
	"ease",
	"aptness",
	"intuitiveness",
	"enthusiasm",
	"partiality",
	"timestamp",
]
## Columns of trials.csv.
const TRIALS_COLUMNS: PackedStringArray = [
	"participant_id",
	"condition",
	"level",
	"trial_index",
	"time_to_goal_s",
	"completed",
	"wall_collisions",
	"contact_time_s",
	"path_length_px",
	"mean_force_n",
	"max_force_n",
	"telemetry_file",
	"timestamp",
]
## Columns of a telemetry file.
const TELEMETRY_COLUMNS: PackedStringArray = [
	"time_s", "input_x", "input_y", "avatar_x", "avatar_y", "force_x", "force_y", "in_contact"
]

const _ID_PATTERN: String = "^[A-Za-z0-9][A-Za-z0-9_-]*$"
const _LEVEL_PATTERN: String = "^[A-Za-z0-9][A-Za-z0-9_.-]*$"
const _INT_PATTERN: String = "^[+-]?[0-9]+$"
const _NUMBER_PATTERN: String = "^[+-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)([eE][+-]?[0-9]+)?$"
const _TIMESTAMP_PATTERN: String = (
	"^[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}(\\.[0-9]{1,9})?"
	+ "(Z|[+-][0-9]{2}:[0-9]{2})$"
)

static var _regexes: Dictionary[String, RegEx] = {}


## The allowed values of the demographic field [param key], in display order.
static func demographic_values(key: String) -> PackedStringArray:
	var values: Array = DEMOGRAPHICS.get(key, [])
	return PackedStringArray(values)


## The demographic fields, in display order.
static func demographic_keys() -> PackedStringArray:
	var keys: Array = DEMOGRAPHICS.keys()
	return PackedStringArray(keys)


## The label of the demographic field [param key].
static func demographic_title(key: String) -> String:
	return str(DEMOGRAPHIC_TITLES.get(key, key))


## The title of [param criterion] ("Realism").
static func criterion_title(criterion: String) -> String:
	var text: Array = CRITERION_TEXT.get(criterion, [criterion, ""])
	return str(text[0])


## The question of [param criterion], the paper's wording ("How realistic is the control
## scheme?").
static func criterion_question(criterion: String) -> String:
	var text: Array = CRITERION_TEXT.get(criterion, [criterion, ""])
	return str(text[1])


## Whether [param id] is a valid participant id ([code][A-Za-z0-9][A-Za-z0-9_-]*[/code]).
static func is_valid_id(id: String) -> bool:
	return _matches(_ID_PATTERN, id)


## Whether [param level] is a valid level id.
static func is_valid_level(level: String) -> bool:
	return _matches(_LEVEL_PATTERN, level)


## Whether [param text] is a CSV integer (optional sign and digits).
static func is_integer(text: String) -> bool:
	return _matches(_INT_PATTERN, text)


## Whether [param text] is a CSV number (decimal, optional exponent; no nan/inf).
static func is_number(text: String) -> bool:
	return _matches(_NUMBER_PATTERN, text)


## Whether [param text] is an RFC 3339 timestamp with a time zone.
static func is_timestamp(text: String) -> bool:
	return _matches(_TIMESTAMP_PATTERN, text)


## The condition's name for people (never shown to participants, who see "Method N").
static func condition_label(condition: String) -> String:
	match condition:
		"none":
			return "No feedback"
		"movement":
			return "Movement-based"
		"constraint":
			return "Constraint-based"
	return condition


## A demographic value as shown on the start screen ("20-29" stays, "non_binary" becomes
## "Non-binary", "under_20" becomes "Under 20").
static func value_label(value: String) -> String:
	match value:
		"under_20":
			return "Under 20"
		"non_binary":
			return "Non-binary"
		"undisclosed":
			return "Prefer not to say"
	return value.capitalize() if not value[0].is_valid_int() else value


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
	return "%s/%s_%d.csv" % [TELEMETRY_DIR, condition, trial_index]


static func _matches(pattern: String, text: String) -> bool:
	if not _regexes.has(pattern):
		_regexes[pattern] = RegEx.create_from_string(pattern)
	return _regexes[pattern].search(text) != null
