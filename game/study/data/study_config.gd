class_name StudyConfig
extends RefCounted
## The maze study's settings: which levels, how many trials, counterbalancing, telemetry
## rate and, per condition, the control scheme and the forces rendered.
##
## Layers, later ones winning: [constant DEFAULT_PATH] (shipped: every setting and its
## default), [code]<study root>/study_config.json[/code] (the researcher's, next to the data;
## the analysis ignores files directly in the study folder) and any files or dictionaries
## given to [method merge_file] / [method merge]. Dictionaries merge key by key (so a file
## may change only [code]conditions.movement.forces.friction[/code]). A setting takes its
## type from the shipped file, except that numbers are whole or bounded only as
## [member numbers] says; [constant CHOICES] and [constant CONTACT_MODEL_SETTINGS] list the
## settings with a fixed set of values.
## Unknown keys and values of the wrong type or range are collected in [member errors];
## the study refuses to start while there are any.
## [codeblock]
## var config := StudyConfig.load_default()
## config.merge({"trials_per_condition": 2})
## if not config.is_valid(): print(config.errors)
## [/codeblock]

## The shipped settings.
const DEFAULT_PATH: String = "res://assets/study/study_config.json"
## Name of the researcher's settings file inside the study root.
const ROOT_FILE: String = "study_config.json"
## Settings (by path) that take one of a few strings.
const CHOICES: Dictionary = {
	"conditions.constraint.update": ["servo", "frame"],
	"conditions.constraint.workspace": ["disc", "square"],
}
## Settings that take one of the data schema's contact models ([member
## StudyFormat.contact_models]: the trials record the one in effect).
const CONTACT_MODEL_SETTINGS: Array[String] = [
	"conditions.none.contact_model", "conditions.movement.contact_model"
]

## The numeric settings that are whole numbers ([code]TYPE_INT[/code]) or bounded, by path:
## [code][type, lowest, highest][/code], the bounds optional; a number not listed may be
## fractional and is unbounded. The telemetry's decimation is also bounded by the servo's
## default rate (the files keep the format's minimum rate).
static var numbers: Dictionary = {
	"trials_per_condition": [TYPE_INT, 1, 50],
	"seed": [TYPE_INT],
	"telemetry_decimation": [TYPE_INT],
	"trial_timeout_s": [TYPE_FLOAT, 1.0, 3600.0],
	"telemetry_flush_s": [TYPE_FLOAT, 0.02, 10.0],
	"contact_gap_s": [TYPE_FLOAT, 0.0, 1.0],
	"centre_tolerance": [TYPE_FLOAT, 0.01, 1.0],
	"autopilot_speed": [TYPE_FLOAT, 10.0, 5000.0],
	"conditions.constraint.max_iterations": [TYPE_INT],
}

## Problems found so far ("key: what"); empty when the settings are usable.
var errors: PackedStringArray = PackedStringArray()
## The merged settings.
var data: Dictionary = {}

# The shipped settings: every key a setting may have, and the type of its value.
var _shape: Dictionary = {}


## The shipped settings ([constant DEFAULT_PATH]), checked like any other layer.
static func load_default() -> StudyConfig:
	var config: StudyConfig = StudyConfig.new()
	config._shape = config._read_object(DEFAULT_PATH)
	config.data = config._shape.duplicate(true)
	config.merge(config._shape, DEFAULT_PATH)
	return config


## Merges the JSON object in [param path] (res://, user:// or absolute). A missing file is
## an error unless [param optional].
func merge_file(path: String, optional: bool = false) -> void:
	if optional and not FileAccess.file_exists(path):
		return
	var values: Dictionary = _read_object(path)
	if not values.is_empty():
		merge(values, path)


## Merges [param values] into the settings, checking each key; [param source] names where
## they came from in error messages.
func merge(values: Dictionary, source: String = "settings") -> void:
	_merge_into(data, values, _shape, source, "")
	if not _shape.is_empty():
		_check_values(source)


## The values the setting at [param path] may take, when they are few (see
## [constant CHOICES]).
static func choices(path: String) -> PackedStringArray:
	if path in CONTACT_MODEL_SETTINGS:
		return StudyFormat.contact_models
	var values: Array = CHOICES.get(path, [])
	return PackedStringArray(values)


## Whether no problem was found.
func is_valid() -> bool:
	return errors.is_empty()


## Folder the participant folders are written to (res:// is refused: it is read-only in
## exported games).
func study_root() -> String:
	return str(data.get("study_root", ""))


## Scene of the maze evaluation level.
func maze_level() -> String:
	return str(data["maze_level"])


## Scenes of the demonstration levels, in practice order.
func demo_levels() -> PackedStringArray:
	var levels: Array = data["demo_levels"]
	return PackedStringArray(levels)


## Conditions offered during practice, in order ("Next method" cycles through them).
func practice_conditions() -> PackedStringArray:
	var conditions: Array = data["practice_conditions"]
	return PackedStringArray(conditions)


## Whether a resumed session starts with the practice again.
func practice_on_resume() -> bool:
	return data["practice_on_resume"] == true


## Maze trials per condition.
func trials_per_condition() -> int:
	return _value("trials_per_condition")


## A fractional setting of [member numbers] by name, e.g. [code]trial_timeout_s[/code]
## (what each means: [code]assets/study/README.md[/code]).
func number(key: String) -> float:
	var rule: Array = numbers.get(key, [])
	if rule.is_empty() or rule[0] != TYPE_FLOAT:
		push_error("StudyConfig: '%s' is not a fractional setting." % key)
		return 0.0
	return _value(key)


## [code]random[/code] or [code]latin_square[/code].
func counterbalancing() -> String:
	return str(data["counterbalancing"])


## Seed of the condition order; -1 draws a fresh one per participant (it is recorded).
func order_seed() -> int:
	return _value("seed")


## Keep every n-th servo sample in the telemetry files.
func telemetry_decimation() -> int:
	return _value("telemetry_decimation")


## The settings of [param name] (see the keys in [constant DEFAULT_PATH]).
func condition(name: String) -> Dictionary:
	var conditions: Dictionary = data["conditions"]
	var settings: Dictionary = conditions.get(name, {})
	return settings


## Whether condition [param name] renders force [param force] (a key of its
## [code]forces[/code] in [constant DEFAULT_PATH]).
func force_enabled(name: String, force: String) -> bool:
	var forces: Dictionary = condition(name).get("forces", {})
	return forces.get(force, false) == true


func _merge_into(
	target: Dictionary, values: Dictionary, shape: Dictionary, source: String, prefix: String
) -> void:
	for key: Variant in values:
		var name: String = str(key)
		var path: String = prefix + name
		if not shape.has(name):
			errors.append("%s: unknown setting '%s'" % [source, path])
			continue
		var expected: Variant = shape[name]
		var value: Variant = values[key]
		if expected is Dictionary:
			if not value is Dictionary:
				errors.append("%s: '%s' must be an object" % [source, path])
				continue
			var inner_target: Dictionary = target[name]
			var inner_values: Dictionary = value
			var inner_shape: Dictionary = expected
			_merge_into(inner_target, inner_values, inner_shape, source, path + ".")
			continue
		var kind: int = _kind(path, expected)
		if not _is_kind(kind, value):
			errors.append(
				(
					"%s: '%s' must be %s, got %s"
					% [source, path, _kind_name(kind), JSON.stringify(value)]
				)
			)
		elif kind == TYPE_INT:
			target[name] = roundi(_as_float(value))
		elif kind == TYPE_FLOAT:
			target[name] = _as_float(value)
		else:
			target[name] = value


func _check_values(source: String) -> void:
	for path: String in numbers:
		var rule: Array = numbers[path]
		if rule.size() == 3:
			_check_range(source, path, _value(path), rule[1], rule[2])
	# The telemetry keeps at least the format's minimum rate at the servo's default rate.
	var servo_rate_hz: float = HapticServoConstants.DEFAULT_RATE_HZ
	var decimation_max: int = maxi(1, floori(servo_rate_hz / StudyFormat.telemetry_min_rate_hz))
	_check_range(source, "telemetry_decimation", _value("telemetry_decimation"), 1, decimation_max)
	for path: String in CHOICES.keys() + CONTACT_MODEL_SETTINGS:
		var allowed: PackedStringArray = choices(path)
		if not str(_value(path)) in allowed:
			errors.append("%s: '%s' must be %s" % [source, path, " or ".join(allowed)])
	var modes: PackedStringArray = StudyFormat.counterbalancing_modes
	if not counterbalancing() in modes:
		errors.append("%s: 'counterbalancing' must be %s" % [source, " or ".join(modes)])
	if study_root().begins_with("res://"):
		errors.append("%s: 'study_root' must not be under res:// (read-only)" % source)
	for name: String in practice_conditions():
		if not name in StudyFormat.conditions:
			errors.append("%s: 'practice_conditions': unknown condition '%s'" % [source, name])
	for name: String in StudyFormat.conditions:
		var control: String = str(condition(name).get("control", ""))
		var wanted: String = "position" if StudyFormat.is_position_control(name) else "acceleration"
		if control != wanted:
			errors.append("%s: 'conditions.%s.control' must be %s" % [source, name, wanted])


func _check_range(
	source: String, path: String, value: Variant, low: Variant, high: Variant
) -> void:
	if _as_float(value) >= _as_float(low) and _as_float(value) <= _as_float(high):
		return
	errors.append("%s: '%s' must be within %s..%s (got %s)" % [source, path, low, high, value])


# The value at a dotted path ("conditions.constraint.update").
func _value(path: String) -> Variant:
	var value: Variant = data
	for key: String in path.split("."):
		if not value is Dictionary:
			return null
		var inner: Dictionary = value
		value = inner.get(key)
	return value


# TYPE_INT or TYPE_FLOAT for a number (see [member numbers]), else the shipped value's type.
static func _kind(path: String, expected: Variant) -> int:
	if typeof(expected) == TYPE_FLOAT or typeof(expected) == TYPE_INT:
		var rule: Array = numbers.get(path, [TYPE_FLOAT])
		return rule[0]
	return typeof(expected)


static func _is_kind(kind: int, value: Variant) -> bool:
	var is_number: bool = typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT
	match kind:
		TYPE_FLOAT:
			return is_number
		TYPE_INT:
			# JSON numbers arrive as floats: whole ones are fine.
			return is_number and is_equal_approx(_as_float(value), roundf(_as_float(value)))
		TYPE_ARRAY:
			if not value is Array:
				return false
			for item: Variant in value:
				if typeof(item) != TYPE_STRING:
					return false
			return true
	return typeof(value) == kind


static func _as_float(value: Variant) -> float:
	var converted: float = value
	return converted


static func _kind_name(kind: int) -> String:
	match kind:
		TYPE_FLOAT:
			return "a number"
		TYPE_INT:
			return "a whole number"
		TYPE_BOOL:
			return "true or false"
		TYPE_STRING:
			return "a string"
		TYPE_ARRAY:
			return "a list of strings"
	return "an object"


func _read_object(path: String) -> Dictionary:
	if not FileAccess.file_exists(path):
		errors.append("%s: file not found" % path)
		return {}
	var json: JSON = JSON.new()
	if json.parse(FileAccess.get_file_as_string(path)) != OK:
		errors.append(
			"%s:%d: invalid JSON: %s" % [path, json.get_error_line(), json.get_error_message()]
		)
		return {}
	if not json.data is Dictionary:
		errors.append("%s: expected a JSON object" % path)
		return {}
	var values: Dictionary = json.data
	return values
