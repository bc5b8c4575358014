class_name StudyConfig
extends RefCounted
## The maze study's settings: which levels, how many trials, counterbalancing, telemetry
## rate and, per condition, the control scheme and the forces rendered.
##
## Layers, later ones winning: the built-in defaults, [constant DEFAULT_PATH] (shipped),
## [code]<study root>/study_config.json[/code] (the researcher's, next to the data; the
## analysis ignores files directly in the study folder) and any files or dictionaries
## given to [method merge_file] / [method merge]. Dictionaries merge key by key (so a
## file may change only [code]conditions.movement.forces.friction[/code]). Unknown keys and
## values of the wrong type or range are collected in [member errors]; the study refuses
## to start while there are any.
## [codeblock]
## var config := StudyConfig.load_default()
## config.merge({"trials_per_condition": 2})
## if not config.is_valid(): print(config.errors)
## [/codeblock]

## The shipped settings.
const DEFAULT_PATH: String = "res://assets/study/study_config.json"
## Name of the researcher's settings file inside the study root.
const ROOT_FILE: String = "study_config.json"
## Forces the movement-based renderer can be asked for, each switchable per condition.
const FORCES: PackedStringArray = ["normal", "friction", "impact", "weight", "water"]
## Servo rate, for the telemetry rate check (Hz).
const SERVO_RATE_HZ: float = 1000.0

## Problems found so far ("key: what"); empty when the settings are usable.
var errors: PackedStringArray = PackedStringArray()
## The merged settings.
var data: Dictionary = {}


func _init() -> void:
	data = _defaults()


## The built-in defaults merged with [constant DEFAULT_PATH].
static func load_default() -> StudyConfig:
	var config: StudyConfig = StudyConfig.new()
	config.merge_file(DEFAULT_PATH)
	return config


## Merges the JSON object in [param path] (res://, user:// or absolute). A missing file is
## an error unless [param optional].
func merge_file(path: String, optional: bool = false) -> void:
	if not FileAccess.file_exists(path):
		if not optional:
			errors.append("%s: file not found" % path)
		return
	var text: String = FileAccess.get_file_as_string(path)
	var json: JSON = JSON.new()
	if json.parse(text) != OK:
		errors.append(
			"%s:%d: invalid JSON: %s" % [path, json.get_error_line(), json.get_error_message()]
		)
		return
	if not json.data is Dictionary:
		errors.append("%s: expected a JSON object" % path)
		return
	var values: Dictionary = json.data
	merge(values, path)


## Merges [param values] into the settings, checking each key; [param source] names where
## they came from in error messages.
func merge(values: Dictionary, source: String = "settings") -> void:
	_merge_into(data, values, _defaults(), source, "")
	_check_ranges(source)


## Whether no problem was found.
func is_valid() -> bool:
	return errors.is_empty()


## Folder the participant folders are written to (res:// is refused: it is read-only in
## exported games).
func study_root() -> String:
	return str(data["study_root"])


## Scene of the maze evaluation level.
func maze_level() -> String:
	return str(data["maze_level"])


## Scenes of the demonstration levels, in practice order.
func demo_levels() -> PackedStringArray:
	return _strings(data["demo_levels"])


## Conditions offered during practice, in order ("Next method" cycles through them).
func practice_conditions() -> PackedStringArray:
	return _strings(data["practice_conditions"])


## Whether a resumed session starts with the practice again.
func practice_on_resume() -> bool:
	var value: bool = data["practice_on_resume"]
	return value


## Maze trials per condition.
func trials_per_condition() -> int:
	var value: int = data["trials_per_condition"]
	return value


## A trial that has not reached the goal after this many seconds ends (completed 0).
func trial_timeout_s() -> float:
	var value: float = data["trial_timeout_s"]
	return value


## [code]random[/code] or [code]latin_square[/code].
func counterbalancing() -> String:
	return str(data["counterbalancing"])


## Seed of the condition order; -1 draws a fresh one per participant (it is recorded).
func order_seed() -> int:
	var value: int = data["seed"]
	return value


## Keep every n-th servo sample in the telemetry files (1–4: 1000–250 Hz).
func telemetry_decimation() -> int:
	var value: int = data["telemetry_decimation"]
	return value


## Telemetry is appended to its file at least this often, in seconds.
func telemetry_flush_s() -> float:
	var value: float = data["telemetry_flush_s"]
	return value


## Two contacts closer in time than this count as one wall collision, in seconds.
func contact_gap_s() -> float:
	var value: float = data["contact_gap_s"]
	return value


## How close to the centre (normalised workspace units) the handle must be to start a trial.
func centre_tolerance() -> float:
	var value: float = data["centre_tolerance"]
	return value


## Speed of the scripted participant's hand along the path in position control, px/s.
func autopilot_speed() -> float:
	var value: float = data["autopilot_speed"]
	return value


## The settings of [param condition] (see the keys in [constant DEFAULT_PATH]).
func condition(name: String) -> Dictionary:
	var conditions: Dictionary = data["conditions"]
	var settings: Dictionary = conditions.get(name, {})
	return settings


## Whether [param condition] renders force [param force] (one of [constant FORCES]).
func force_enabled(name: String, force: String) -> bool:
	var forces: Dictionary = condition(name).get("forces", {})
	var value: bool = forces.get(force, false)
	return value


## The settings as JSON (recorded nowhere by default; useful in reports).
func to_json() -> String:
	return JSON.stringify(data, "  ")


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
		elif not _same_kind(expected, value):
			errors.append(
				(
					"%s: '%s' must be %s, got %s"
					% [source, path, _kind_name(expected), JSON.stringify(value)]
				)
			)
		elif typeof(expected) == TYPE_INT:
			var whole: int = roundi(_as_float(value))
			target[name] = whole
		elif typeof(expected) == TYPE_FLOAT:
			target[name] = _as_float(value)
		else:
			target[name] = value


func _check_ranges(source: String) -> void:
	_check_int(source, "trials_per_condition", 1, 50)
	_check_int(source, "telemetry_decimation", 1, 4)
	_check_float(source, "trial_timeout_s", 1.0, 3600.0)
	_check_float(source, "telemetry_flush_s", 0.02, 10.0)
	_check_float(source, "contact_gap_s", 0.0, 1.0)
	_check_float(source, "centre_tolerance", 0.01, 1.0)
	_check_float(source, "autopilot_speed", 10.0, 5000.0)
	if not str(data["counterbalancing"]) in StudyFormat.COUNTERBALANCING:
		errors.append("%s: 'counterbalancing' must be random or latin_square" % source)
	if study_root().begins_with("res://"):
		errors.append("%s: 'study_root' must not be under res:// (read-only)" % source)
	for name: String in practice_conditions():
		if not name in StudyFormat.CONDITIONS:
			errors.append("%s: 'practice_conditions': unknown condition '%s'" % [source, name])
	for name: String in StudyFormat.CONDITIONS:
		var settings: Dictionary = condition(name)
		var control: String = str(settings.get("control", ""))
		if name == "constraint" and control != "position":
			errors.append("%s: 'conditions.constraint.control' must be position" % source)
		elif name != "constraint" and control != "acceleration":
			errors.append("%s: 'conditions.%s.control' must be acceleration" % [source, name])
	var constraint: Dictionary = condition("constraint")
	if not str(constraint.get("update", "")) in ["servo", "frame"]:
		errors.append("%s: 'conditions.constraint.update' must be servo or frame" % source)
	if not str(constraint.get("workspace", "")) in ["disc", "square"]:
		errors.append("%s: 'conditions.constraint.workspace' must be disc or square" % source)


func _check_int(source: String, key: String, low: int, high: int) -> void:
	var value: int = data[key]
	if value < low or value > high:
		errors.append("%s: '%s' must be within %d..%d (got %d)" % [source, key, low, high, value])


func _check_float(source: String, key: String, low: float, high: float) -> void:
	var value: float = data[key]
	if not (value >= low and value <= high):
		errors.append("%s: '%s' must be within %s..%s (got %s)" % [source, key, low, high, value])


static func _same_kind(expected: Variant, value: Variant) -> bool:
	match typeof(expected):
		TYPE_FLOAT:
			return typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT
		TYPE_INT:
			# JSON numbers arrive as floats: whole ones are fine.
			var number_ok: bool = typeof(value) == TYPE_FLOAT or typeof(value) == TYPE_INT
			return number_ok and is_equal_approx(_as_float(value), roundf(_as_float(value)))
		TYPE_ARRAY:
			if not value is Array:
				return false
			for item: Variant in value:
				if typeof(item) != TYPE_STRING:
					return false
			return true
	return typeof(value) == typeof(expected)


static func _as_float(value: Variant) -> float:
	var number: float = value
	return number


static func _kind_name(expected: Variant) -> String:
	match typeof(expected):
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


static func _strings(value: Variant) -> PackedStringArray:
	var out: PackedStringArray = PackedStringArray()
	if value is Array:
		for item: Variant in value:
			out.append(str(item))
	return out


static func _acceleration(force_scale: float, normal: bool) -> Dictionary:
	return {
		"control": "acceleration",
		"force_scale": force_scale,
		"forces":
		{"normal": normal, "friction": false, "impact": false, "weight": false, "water": false},
		"stiffness": 2.0,
		"friction": 1.0,
		"impact_gain": 0.5,
		"smoothing": true,
	}


static func _defaults() -> Dictionary:
	return {
		"format_version": 1,
		"study_root": "user://study",
		"maze_level": "res://scenes/study/levels/maze.tscn",
		"demo_levels":
		[
			"res://scenes/study/levels/demo_open.tscn",
			"res://scenes/study/levels/demo_corridors.tscn",
		],
		"practice_conditions": ["movement", "constraint", "none"],
		"practice_on_resume": false,
		"trials_per_condition": 1,
		"trial_timeout_s": 180.0,
		"counterbalancing": "random",
		"seed": -1,
		"telemetry_decimation": 2,
		"telemetry_flush_s": 0.5,
		"contact_gap_s": 0.04,
		"centre_tolerance": 0.05,
		"autopilot_speed": 260.0,
		"conditions":
		{
			"none": _acceleration(0.0, false),
			"movement": _acceleration(1.0, true),
			"constraint":
			{
				"control": "position",
				"stiffness": 300.0,
				"update": "servo",
				"workspace": "disc",
				"half_extent": 0.0,
				"max_iterations": 6,
			},
		},
	}
