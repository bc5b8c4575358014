class_name TelemetryMetrics
extends RefCounted
## A trial's measures, accumulated row by row from its telemetry file's records as written
## (the text fields, so rounding is what a reader of the file gets): FORMAT.md, "Trial
## metrics", defines each one on the rows, and this is that definition.
## [br][br]
## Rows are [code]time_s, input_x, input_y, avatar_x, avatar_y, force_x, force_y,
## in_contact[/code] (the schema's telemetry columns, in order).

## Rows seen.
var rows: int = 0
## Sum of the rows' force magnitudes |(force_x, force_y)|, newtons.
var force_sum_n: float = 0.0
## Largest force magnitude of a row, newtons.
var max_force_n: float = 0.0
## Time in contact: each row with in_contact 1 counts the time since the row before it
## (at most [member StudyFormat.metric_max_row_step_s]), seconds.
var contact_time_s: float = 0.0
## Contact onsets: a row in contact more than the gap after the last row in contact.
var collisions: int = 0
## Sum of the distances between consecutive rows' avatar positions, level pixels.
var path_length_px: float = 0.0

var _last_t: float = -INF
var _last_contact_t: float = -INF
var _last_avatar: Vector2 = Vector2.ZERO


## Adds one row ([param fields]: the record's fields as written); [param contact_gap_s]:
## contacts closer than this are one collision.
func add_row(fields: PackedStringArray, contact_gap_s: float) -> void:
	var t: float = fields[0].to_float()
	var avatar: Vector2 = Vector2(fields[3].to_float(), fields[4].to_float())
	var force: float = Vector2(fields[5].to_float(), fields[6].to_float()).length()
	var in_contact: bool = fields[7] == "1"
	force_sum_n += force
	max_force_n = maxf(max_force_n, force)
	if rows > 0:
		path_length_px += avatar.distance_to(_last_avatar)
	if in_contact:
		if rows > 0:
			contact_time_s += clampf(t - _last_t, 0.0, StudyFormat.metric_max_row_step_s)
		if t - _last_contact_t > contact_gap_s:
			collisions += 1
		_last_contact_t = t
	_last_t = t
	_last_avatar = avatar
	rows += 1


## The mean of the rows' force magnitudes (rows are equally spaced in time, so this is
## the time average), newtons; 0 without rows.
func mean_force() -> float:
	return force_sum_n / rows if rows > 0 else 0.0
