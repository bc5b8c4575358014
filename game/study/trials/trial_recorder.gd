class_name TrialRecorder
extends RefCounted
## Measures one maze trial and writes its servo telemetry (FORMAT.md).
##
## Fed once per physics tick ([method tick]) with the avatar's position, it drains the
## servo's 1 kHz telemetry and keeps every [member decimation]-th sample as a row of the
## telemetry file, in game axes (y down): input is the device position over the workspace
## radius, avatar the avatar's position in level pixels (between physics ticks interpolated;
## in position control the proxy, recovered exactly from the constraint force:
## proxy = device + F/k_c), force the rendered total, in_contact the frame's contact flag
## (acceleration control) or the proxy-held flag (position control). Every measure is
## computed from the rows as written (the numbers the file holds, after rounding), so a
## reader recomputes them from the file (FORMAT.md, "Trial metrics"): the rendered force's
## mean and maximum x-y magnitude, the time in contact, the wall collisions (contact onsets;
## a contact that resumes within [member contact_gap_s] continues the same collision) and
## the path length. Lines are appended in chunks every [member flush_s] seconds and at the
## end, each chunk one durable write.

## The trial's measures, filled by [method finish].
var result: TrialResult = null
## Keep every n-th servo sample in the file.
var decimation: int = 2
## Append to the file at least this often, seconds.
var flush_s: float = 0.5
## Contacts separated by less than this are one collision, seconds.
var contact_gap_s: float = 0.04
## Why a write failed; empty while all is well.
var error: String = ""

var _store: StudyStore = null
var _map: MazeMap = null
var _position_control: bool = false
var _stiffness: float = 0.0
var _stride: int = 0
# The flags column's bit that says "touching a wall": the frame's contact (acceleration
# control) or the proxy held by a wall (position control).
var _contact_flag: int = 0
var _col: Dictionary[String, int] = {}
var _lines: PackedStringArray = PackedStringArray()
var _since_flush: float = 0.0
var _t0: float = -1.0
var _sample_count: int = 0
var _prev_avatar: Vector2 = Vector2.ZERO
var _metrics: TelemetryMetrics = TelemetryMetrics.new()


## A recorder for trial [param trial_index] of [param condition] on [param level_id];
## [param map] and [param stiffness] (k_c) recover the proxy in position control.
func _init(
	store: StudyStore,
	condition: String,
	level_id: String,
	trial_index: int,
	map: MazeMap,
	stiffness: float
) -> void:
	_store = store
	_map = map
	_stiffness = stiffness
	_position_control = StudyFormat.is_position_control(condition)
	result = TrialResult.new()
	result.condition = condition
	result.level = level_id
	result.trial_index = trial_index
	result.telemetry_file = StudyFormat.telemetry_name(condition, trial_index)
	# As the renderer has it (the rig set it up for the condition), not as the settings asked.
	if not _position_control:
		var model: int = HapticsMovement.of(Haptics).get_settings().force_model.contact_model
		result.contact_model = HapticsValue.choice_name(HapticMovementFacts.ContactModel, model)
	_contact_flag = (
		HapticConstraintFacts.TELEMETRY_FLAG_PROXY_CONTACT
		if _position_control
		else HapticServoConstants.TELEMETRY_FLAG_CONTACT
	)
	var names: PackedStringArray = Haptics.servo.get_telemetry_columns()
	_stride = names.size()
	for i: int in names.size():
		_col[names[i]] = i


## Starts the trial: discards older telemetry and creates the file with its header.
## Returns false when the file cannot be written.
func begin(avatar: Vector2) -> bool:
	_prev_avatar = avatar
	_drain_all()
	if not _store.append_telemetry(result.telemetry_file, ""):
		error = _store.last_error
		return false
	return true


## One physics tick: [param avatar] is the avatar's position now (maze units), [param delta]
## the tick. Returns false when a write failed (see [member error]).
func tick(avatar: Vector2, delta: float) -> bool:
	_process_samples(_drain(), avatar)
	_prev_avatar = avatar
	_since_flush += delta
	if _since_flush >= flush_s:
		return flush()
	return true


## Appends the buffered lines to the telemetry file.
func flush() -> bool:
	_since_flush = 0.0
	if _lines.is_empty():
		return true
	var text: String = "".join(_lines)
	_lines.clear()
	if not _store.append_telemetry(result.telemetry_file, text):
		error = _store.last_error
		return false
	return true


## Ends the trial at [param avatar] after [param time_s] seconds: the last samples are
## processed and written, and [member result] is filled in. Returns false when the final
## write failed.
func finish(avatar: Vector2, time_s: float, completed: bool) -> bool:
	_process_samples(_drain(), avatar)
	_prev_avatar = avatar
	result.time_s = time_s
	result.completed = completed
	result.wall_collisions = _metrics.collisions
	result.contact_time_s = minf(_metrics.contact_time_s, time_s)
	result.path_length_px = _metrics.path_length_px
	result.mean_force_n = _metrics.mean_force()
	result.max_force_n = _metrics.max_force_n
	return flush()


func _drain() -> PackedFloat32Array:
	return Haptics.servo.drain_telemetry(HapticServoConstants.TELEMETRY_QUEUE_CAPACITY)


func _drain_all() -> void:
	for i: int in 64:
		if _drain().is_empty():
			return


func _process_samples(samples: PackedFloat32Array, avatar: Vector2) -> void:
	var count: int = floori(float(samples.size()) / _stride) if _stride > 0 else 0
	if count == 0 or _col.is_empty():
		return
	var radius: float = maxf(_map.device_radius_m, 1e-9)
	for i: int in count:
		var base: int = i * _stride
		var t: float = samples[base + _col["t"]]
		if _t0 < 0.0:
			_t0 = t
		if _sample_count % decimation == 0:
			var device: Vector2 = Vector2(
				samples[base + _col["position_x"]], -samples[base + _col["position_y"]]
			)
			var force: Vector2 = Vector2(
				samples[base + _col["total_x"]], -samples[base + _col["total_y"]]
			)
			var flags: int = roundi(samples[base + _col["flags"]])
			var where: Vector2 = _avatar_at(samples, base, device, i, count, avatar)
			var input: Vector2 = (device / radius).clamp(-Vector2.ONE, Vector2.ONE)
			var fields: PackedStringArray = PackedStringArray(
				[
					StudyFormat.number(t - _t0, 4),
					StudyFormat.number(input.x, 4),
					StudyFormat.number(input.y, 4),
					StudyFormat.number(where.x, 2),
					StudyFormat.number(where.y, 2),
					StudyFormat.number(force.x, 4),
					StudyFormat.number(force.y, 4),
					"1" if (flags & _contact_flag) != 0 else "0",
				]
			)
			_lines.append(StudyFormat.csv_line(fields))
			_metrics.add_row(fields, contact_gap_s)
		_sample_count += 1


# The avatar at sample i of the n drained this tick: in position control the proxy
# recovered from the constraint force; otherwise interpolated between the last tick's
# position and this one's.
func _avatar_at(
	samples: PackedFloat32Array, base: int, device: Vector2, i: int, n: int, avatar: Vector2
) -> Vector2:
	if _position_control and _stiffness > 1e-6:
		var normal: Vector2 = Vector2(
			samples[base + _col["normal_x"]], -samples[base + _col["normal_y"]]
		)
		return _map.point_of_metres(device + normal / _stiffness)
	return _prev_avatar.lerp(avatar, float(i + 1) / n)
