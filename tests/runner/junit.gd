extends RefCounted
## Writes test results as JUnit XML (the schema CI servers read: testsuites > testsuite >
## testcase, with failure and skipped children).

const Result := preload("res://tests/runner/result.gd")


## Writes [param results] to [param path] (any path FileAccess accepts).
static func write(path: String, results: Array[Result]) -> Error:
	var suites: Dictionary[String, Array] = {}
	var order: PackedStringArray = PackedStringArray()
	for result: Result in results:
		if not suites.has(result.script_path):
			suites[result.script_path] = []
			order.append(result.script_path)
		suites[result.script_path].append(result)

	var body: PackedStringArray = PackedStringArray()
	var total: Array[int] = [0, 0, 0]
	var total_time: float = 0.0
	for script_path: String in order:
		var cases: Array = suites[script_path]
		var counts: Array[int] = [0, 0, 0]
		var time: float = 0.0
		var lines: PackedStringArray = PackedStringArray()
		for item: Variant in cases:
			var result: Result = item
			counts[0] += 1
			time += result.duration_seconds
			lines.append(_testcase(result))
			if result.is_failed():
				counts[1] += 1
			elif result.is_skipped():
				counts[2] += 1
		var first: Result = cases[0]
		body.append(
			(
				(
					'  <testsuite name="%s" file="%s" tests="%d" failures="%d" errors="0"'
					+ ' skipped="%d" time="%.3f">'
				)
				% [_esc(first.suite_name), _esc(script_path), counts[0], counts[1], counts[2], time]
			)
		)
		body.append_array(lines)
		body.append("  </testsuite>")
		for i: int in 3:
			total[i] += counts[i]
		total_time += time

	var text: String = '<?xml version="1.0" encoding="UTF-8"?>\n'
	text += (
		'<testsuites name="godot" tests="%d" failures="%d" errors="0" skipped="%d" time="%.3f">\n'
		% [total[0], total[1], total[2], total_time]
	)
	text += "\n".join(body) + ("\n" if not body.is_empty() else "")
	text += "</testsuites>\n"

	var dir_error: Error = DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	if dir_error != OK and dir_error != ERR_ALREADY_EXISTS:
		return dir_error
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	if file == null:
		return FileAccess.get_open_error()
	file.store_string(text)
	file.close()
	return OK


static func _testcase(result: Result) -> String:
	var head: String = (
		'    <testcase name="%s" classname="%s" time="%.3f"'
		% [_esc(result.test_name), _esc(result.script_path), result.duration_seconds]
	)
	if result.is_failed():
		return (
			'%s>\n      <failure message="%s">%s</failure>\n    </testcase>'
			% [head, _esc(result.failures[0]), _esc("\n".join(result.failures))]
		)
	if result.is_skipped():
		return (
			'%s>\n      <skipped message="%s"/>\n    </testcase>' % [head, _esc(result.skip_reason)]
		)
	return head + "/>"


static func _esc(text: String) -> String:
	return text.xml_escape(true)
