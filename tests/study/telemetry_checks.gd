extends RefCounted
## Measures a trial's telemetry file against the maze's walls and a condition's force law,
## for the tests of the participant who touches the walls. Each function returns numbers
## (shares, worst deviations, durations); the tests put the bounds on them.
## [br][br]
## Rows are [code]PackedFloat64Array[/code]s of the schema's telemetry columns, in order:
## time_s, input_x, input_y, avatar_x, avatar_y, force_x, force_y, in_contact.

const Geometry := preload("res://tests/study/wall_geometry.gd")

## Column indices.
const T: int = 0
const INPUT: int = 1
const AVATAR: int = 3
const FORCE: int = 5
const CONTACT: int = 7
## Within this of a wall's surface (pixels) the avatar counts as touching it: the physics'
## safe margin, rounding to 0.01 px and the interpolation between physics ticks.
const TOUCH_PX: float = 1.0
## A force into a wall stronger than this (newtons) is a pull.
const PULL_N: float = 0.02
## How long after the avatar left a wall a force toward it still counts as a pull toward
## it, seconds.
const RECENT_WALL_S: float = 0.2

var geometry: Geometry = null
## The servo's input dead zone ([member HapticInputSettings.dead_zone]): the input vector the
## force model uses is the file's input with it applied (core/servo/input_vector.h).
var dead_zone: float = 0.0


func _init(p_geometry: Geometry) -> void:
	geometry = p_geometry


## The rows of the telemetry file at [param path] (its header skipped).
static func read_rows(path: String) -> Array[PackedFloat64Array]:
	var rows: Array[PackedFloat64Array] = []
	var text: String = FileAccess.get_file_as_string(path)
	var lines: PackedStringArray = text.split("\n", false)
	for i: int in range(1, lines.size()):
		var row: PackedFloat64Array = PackedFloat64Array()
		for field: String in lines[i].split(","):
			row.append(field.to_float())
		rows.append(row)
	return rows


## The trial's metrics recomputed from [param rows] as FORMAT.md defines them ("Trial
## metrics"), written independently of the game's [TelemetryMetrics].
static func metrics(rows: Array[PackedFloat64Array], contact_gap_s: float) -> Dictionary:
	var force_sum: float = 0.0
	var largest: float = 0.0
	var contact: float = 0.0
	var collisions: int = 0
	var path: float = 0.0
	var last_contact: float = -INF
	for i: int in rows.size():
		var row: PackedFloat64Array = rows[i]
		var force: float = _vec(row, FORCE).length()
		force_sum += force
		largest = maxf(largest, force)
		if i > 0:
			path += _vec(row, AVATAR).distance_to(_vec(rows[i - 1], AVATAR))
		if row[CONTACT] > 0.5:
			if i > 0:
				var step: float = row[T] - rows[i - 1][T]
				contact += clampf(step, 0.0, StudyFormat.metric_max_row_step_s)
			if row[T] - last_contact > contact_gap_s:
				collisions += 1
			last_contact = row[T]
	return {
		"mean_force_n": force_sum / rows.size() if not rows.is_empty() else 0.0,
		"max_force_n": largest,
		"contact_time_s": contact,
		"wall_collisions": collisions,
		"path_length_px": path,
	}


## How the in_contact flags agree with the walls: [code]share[/code] of rows where the flag
## is set exactly when the avatar is within [constant TOUCH_PX] of a wall's surface, and
## [code]closest[/code], the avatar's smallest distance to a wall (negative: inside one).
func contact_agreement(rows: Array[PackedFloat64Array]) -> Dictionary:
	var agree: int = 0
	var closest: float = INF
	for row: PackedFloat64Array in rows:
		var distance: float = geometry.distance(_vec(row, AVATAR)) - Player.RADIUS
		closest = minf(closest, distance + Player.RADIUS)
		if (distance <= TOUCH_PX) == (row[CONTACT] > 0.5):
			agree += 1
	return {"share": float(agree) / maxi(1, rows.size()), "closest": closest}


## Acceleration control: [code]excess[/code], the most a row's force exceeds
## [param overshoot] × k × the largest input ([method model_input]) of the last
## [param window] rows;
## [code]largest[/code] force and [code]largest_input[/code].
func force_bound(
	rows: Array[PackedFloat64Array], k: float, overshoot: float, window: int
) -> Dictionary:
	var excess: float = -INF
	var largest: float = 0.0
	var largest_input: float = 0.0
	for i: int in rows.size():
		var most: float = 0.0
		for j: int in range(maxi(0, i - window), i + 1):
			most = maxf(most, model_input(rows[j]).length())
		var force: float = _vec(rows[i], FORCE).length()
		excess = maxf(excess, force - overshoot * k * most)
		largest = maxf(largest, force)
		largest_input = maxf(largest_input, most)
	return {"excess": excess, "largest": largest, "largest_input": largest_input}


## The paper's normal force against one wall, F = -k (i.n) n, on the rows where it has
## settled: in contact with a single wall (the same one) and an input that moved less than
## [param steady_input] for the last [param window] rows, pressing into it. Returns
## [code]rows[/code] (how many) and [code]worst[/code] (largest |F - expected|, newtons).
func normal_force_law(
	rows: Array[PackedFloat64Array], k: float, window: int, steady_input: float
) -> Dictionary:
	var count: int = 0
	var worst: float = 0.0
	for i: int in range(window, rows.size()):
		var normals: Array[Vector2] = _normals(rows[i])
		if normals.size() != 1 or _normals(rows[i - window]) != normals:
			continue
		var steady: bool = true
		for j: int in range(i - window, i + 1):
			steady = steady and rows[j][CONTACT] > 0.5
			steady = (
				steady and _vec(rows[j], INPUT).distance_to(_vec(rows[i], INPUT)) < steady_input
			)
		var normal: Vector2 = normals[0]
		var press: float = model_input(rows[i]).dot(normal)
		if not steady or press > -0.05:
			continue
		var expected: Vector2 = -k * press * normal
		worst = maxf(worst, _vec(rows[i], FORCE).distance_to(expected))
		count += 1
	return {"rows": count, "worst": worst}


## The pulls into a wall after the hand turned away from it, as runs of rows, each run's
## duration in seconds (rows × the row spacing), ascending:
## [code]rendered[/code], the paper's model pulling: the frame still has a contact (the
## in_contact flag) while the input points away from a wall the avatar touches (or left
## less than [constant RECENT_WALL_S] ago), so
## F_n = -k (i.n) n points into it by more than [constant PULL_N] (k (i.n) > PULL_N);
## [code]felt[/code], the recorded force pointing into a touched wall by more than PULL_N
## (the rendered pull after the servo's smoothing, which lags and stretches it);
## [code]releases[/code], how often the input turned from pressing a touched wall to
## pointing away from it.
func pulls(rows: Array[PackedFloat64Array], k: float) -> Dictionary:
	var rendered: Array[float] = []
	var felt: Array[float] = []
	var releases: int = 0
	var runs: PackedInt32Array = PackedInt32Array([0, 0])
	var spacing: float = row_spacing(rows)
	# The walls last touched stay the ones to pull toward for a while after the avatar
	# left them (the frame and the smoothed force lag behind it).
	var recent: Array[Vector2] = []
	var recent_t: float = -INF
	for i: int in rows.size():
		var model_pull: bool = false
		var force_pull: bool = false
		var touching: Array[Vector2] = _normals(rows[i])
		if not touching.is_empty():
			recent = touching
			recent_t = rows[i][T]
		elif rows[i][T] - recent_t > RECENT_WALL_S:
			recent = []
		for normal: Vector2 in recent:
			var away: float = model_input(rows[i]).dot(normal)
			model_pull = model_pull or (rows[i][CONTACT] > 0.5 and k * away > PULL_N)
			force_pull = force_pull or _vec(rows[i], FORCE).dot(normal) < -PULL_N
			if i > 0 and rows[i - 1][CONTACT] > 0.5:
				if _vec(rows[i - 1], INPUT).dot(normal) <= 0.0 and away > 0.0:
					releases += 1
		_count_run(runs, 0, model_pull, rendered, spacing)
		_count_run(runs, 1, force_pull, felt, spacing)
	_count_run(runs, 0, false, rendered, spacing)
	_count_run(runs, 1, false, felt, spacing)
	rendered.sort()
	felt.sort()
	return {"rendered": rendered, "felt": felt, "releases": releases}


## Position control: on the rows where the proxy is held ([code]in_contact[/code]) by a
## single wall with some force, [code]off_surface[/code] (largest |distance to the wall -
## radius|, pixels) and [code]off_normal[/code] (largest 1 - F.n/|F|); [code]free_force[/code],
## the largest force on rows whose last [param window] rows were all free; [code]reach[/code],
## the largest distance from the proxy to the device's point in the maze (pixels).
func proxy_law(rows: Array[PackedFloat64Array], map: MazeMap, window: int) -> Dictionary:
	var held: int = 0
	var off_surface: float = 0.0
	var off_normal: float = 0.0
	var free_force: float = 0.0
	var reach: float = 0.0
	for i: int in rows.size():
		var proxy: Vector2 = _vec(rows[i], AVATAR)
		var force: Vector2 = _vec(rows[i], FORCE)
		reach = maxf(reach, proxy.distance_to(map.point_of_hand(_vec(rows[i], INPUT))))
		var normals: Array[Vector2] = _normals(rows[i])
		if rows[i][CONTACT] > 0.5 and normals.size() == 1 and force.length() > 0.05:
			held += 1
			var surface: float = geometry.distance(proxy) - Player.RADIUS
			off_surface = maxf(off_surface, absf(surface))
			off_normal = maxf(off_normal, 1.0 - force.dot(normals[0]) / force.length())
		var free: bool = i >= window
		for j: int in range(maxi(0, i - window), i + 1):
			free = free and rows[j][CONTACT] < 0.5
		if free:
			free_force = maxf(free_force, force.length())
	return {
		"held": held,
		"off_surface": off_surface,
		"off_normal": off_normal,
		"free_force": free_force,
		"reach": reach,
	}


## The input vector the force model used for [param row]: the file's input (device
## position over the workspace radius) with the [member dead_zone] applied.
func model_input(row: PackedFloat64Array) -> Vector2:
	var device: Vector2 = _vec(row, INPUT).limit_length(1.0)
	var length: float = device.length()
	if length <= dead_zone:
		return Vector2.ZERO
	return device / length * (length - dead_zone) / (1.0 - dead_zone)


## The median time between rows, seconds.
static func row_spacing(rows: Array[PackedFloat64Array]) -> float:
	var steps: Array[float] = []
	for i: int in range(1, rows.size()):
		steps.append(rows[i][T] - rows[i - 1][T])
	if steps.is_empty():
		return 0.0
	steps.sort()
	return steps[steps.size() >> 1]


# Extends run [param which] of [param runs] while [param on]; when it ends, appends its
# duration to [param out].
static func _count_run(
	runs: PackedInt32Array, which: int, on: bool, out: Array[float], spacing: float
) -> void:
	if on:
		runs[which] += 1
	elif runs[which] > 0:
		out.append(runs[which] * spacing)
		runs[which] = 0


func _normals(row: PackedFloat64Array) -> Array[Vector2]:
	return geometry.normals_within(_vec(row, AVATAR), Player.RADIUS + TOUCH_PX)


static func _vec(row: PackedFloat64Array, column: int) -> Vector2:
	return Vector2(row[column], row[column + 1])
