extends TestSuite
## Tests of the test runner itself, in-process: the assertions, the helpers, discovery.
## Whole runs over the fixtures are checked in a subprocess by test_runner_runs.gd.

const Discovery := preload("res://tests/runner/discovery.gd")

const FALLING_BODY_SCENE: String = "res://tests/fixtures/scenes/falling_body.tscn"
## Every GDScript file of the runner and its fixtures, checked for GDScript warnings.
const OWN_SCRIPTS: PackedStringArray = [
	"res://tests/runner/discovery.gd",
	"res://tests/runner/error_capture.gd",
	"res://tests/runner/junit.gd",
	"res://tests/runner/options.gd",
	"res://tests/runner/result.gd",
	"res://tests/runner/runner.gd",
	"res://tests/runner/test_suite.gd",
	"res://tests/test_runner_runs.gd",
	"res://tests/test_runner_self.gd",
	"res://tests/fixtures/failing/test_fixture_failing.gd",
	"res://tests/fixtures/failing/test_fixture_failing_before_all.gd",
	"res://tests/fixtures/passing/test_fixture_passing.gd",
	"res://tests/fixtures/quitting/test_fixture_quitting.gd",
]


func test_failed_assertion_reports_file_line_and_message() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var returned: bool = probe.assert_eq(1, 2, "one is not two")
	var line: int = get_stack()[0]["line"]
	assert_false(returned)
	assert_eq(
		result.failures,
		PackedStringArray(
			["res://tests/test_runner_self.gd:%d: one is not two: expected 2, got 1" % (line - 1)]
		)
	)


func test_each_assertion_fails_on_bad_input() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var outcomes: Array[bool] = [
		probe.assert_eq("1", 1),
		probe.assert_ne(2, 2.0),
		probe.assert_true(1),
		probe.assert_false(null),
		probe.assert_null(self),
		probe.assert_not_null(null),
		probe.assert_almost_eq(1.0, 1.2, 0.1),
		probe.assert_almost_eq(Vector2(0, 0), Vector2(0, 0.5), 0.1),
		probe.assert_almost_eq(Vector3(0, 0, 0), Vector3(0, 0, 0.5), 0.1),
		probe.assert_almost_eq(Vector3.ZERO, Vector2.ZERO, 0.1),
		probe.assert_gt(1, 1),
		probe.assert_lt(2, 1.5),
		probe.assert_gt("a", 1),
		probe.assert_has([1, 2], 3),
		probe.assert_has({"a": 1}, "b"),
		probe.assert_has("abc", "d"),
		probe.assert_has(PackedInt32Array([1]), 2),
		probe.assert_has(5, 5),
	]
	probe.fail("explicit")
	assert_false(outcomes.has(true), "every assertion returned false: %s" % [outcomes])
	assert_eq(result.failures.size(), outcomes.size() + 1, "\n".join(result.failures))
	assert_has(result.failures[0], 'expected 1, got "1"')
	assert_has(result.failures[9], "cannot compare (0.0, 0.0, 0.0) with (0.0, 0.0)")
	assert_has(result.failures[17], "5 is not a container")
	assert_has(result.failures[18], "explicit")


func test_each_assertion_passes_on_good_input() -> void:
	var probe: TestSuite = _probe()
	var result: TestResult = _bind_probe(probe)
	var freed: Node = Node.new()
	freed.free()
	var outcomes: Array[bool] = [
		probe.assert_eq(2, 2.0),
		probe.assert_eq(&"name", "name"),
		probe.assert_eq(null, null),
		probe.assert_ne(self, null),
		probe.assert_null(freed),
		probe.assert_almost_eq(1, 1.05, 0.1),
		probe.assert_almost_eq(Vector2i(1, 2), Vector2(1.01, 2.0), 0.1),
		probe.assert_almost_eq(Color(0.5, 0.5, 0.5), Color(0.5, 0.51, 0.5), 0.02),
		probe.assert_gt(2.5, 2),
		probe.assert_lt("a", "b"),
		probe.assert_has(PackedVector2Array([Vector2.ONE]), Vector2.ONE),
		probe.assert_has(&"string name", "name"),
	]
	assert_false(outcomes.has(false), "every assertion returned true: %s" % [outcomes])
	assert_eq(result.failures, PackedStringArray())


func test_expected_engine_error_does_not_fail() -> void:
	expect_error('Node not found: "no_such_child"')
	assert_null(get_node_or_null("no_such_child"))
	get_node("no_such_child")


func test_timeout_can_be_raised_for_one_test() -> void:
	set_timeout(60.0)
	await wait_physics_frames(1)


func test_instances_a_scene_and_steps_physics() -> void:
	var scene: PackedScene = load(FALLING_BODY_SCENE) as PackedScene
	if not assert_not_null(scene):
		return
	var root: Node = add_child_autofree(scene.instantiate())
	var ball: RigidBody2D = root.get_node("Ball") as RigidBody2D
	var start: Vector2 = ball.global_position
	await wait_physics_frames(10)
	assert_gt(ball.global_position.y - start.y, 5.0, "gravity moved the body down")
	assert_almost_eq(ball.global_position.x, start.x, 0.001)


func test_autoloads_are_available() -> void:
	var checked: int = 0
	for property: Dictionary in ProjectSettings.get_property_list():
		var setting: String = property["name"]
		if not setting.begins_with("autoload/"):
			continue
		var autoload_name: String = setting.trim_prefix("autoload/")
		var script_path: String = str(ProjectSettings.get_setting(setting)).trim_prefix("*")
		if not ResourceLoader.exists(script_path):
			continue
		assert_not_null(get_node_or_null("/root/" + autoload_name), autoload_name)
		checked += 1
	if checked == 0:
		skip("no autoload script exists yet")


func test_default_discovery_skips_fixtures_and_runner() -> void:
	var found: PackedStringArray = Discovery.discover("res://tests")
	assert_has(found, "res://tests/test_runner_self.gd")
	for path: String in found:
		assert_false(path.begins_with("res://tests/fixtures/"), path)
		assert_false(path.begins_with("res://tests/runner/"), path)
	var fixtures: PackedStringArray = Discovery.discover("res://tests/fixtures/passing")
	assert_eq(fixtures, PackedStringArray(["res://tests/fixtures/passing/test_fixture_passing.gd"]))


func test_own_scripts_have_no_gdscript_warnings() -> void:
	var enabled: int = await assert_scripts_compile_without_warnings(OWN_SCRIPTS)
	assert_gt(enabled, 0, "project.godot enables some GDScript warnings")


## A suite instance that is not run: its assertions record into a result we inspect.
func _probe() -> TestSuite:
	var probe: TestSuite = TestSuite.new()
	autofree(probe)
	return probe


func _bind_probe(probe: TestSuite) -> TestResult:
	var result: TestResult = TestResult.new("probe", "probe", "")
	probe._runner_bind_result(result)
	return result
