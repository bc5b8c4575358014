extends TestSuite
## The study's data schema (assets/study/study_schema.json) as the game reads it: the CSV
## columns with their types and ranges, the check of single fields, the file names, and
## the resume scanner reading records by column name (CRLF tolerated, quotes refused).

const Support := preload("res://tests/study/study_test_support.gd")

var _root: String = ""


func before_each() -> void:
	_root = Support.fresh_root("schema")


func after_each() -> void:
	Support.remove_tree(_root)


func test_the_ratings_have_a_column_per_criterion() -> void:
	var columns: Array[Dictionary] = StudyFormat.columns("ratings")
	assert_eq(columns.size(), 3 + StudyFormat.criteria.size() + 1)
	for i: int in StudyFormat.criteria.size():
		assert_eq(str(columns[3 + i]["name"]), StudyFormat.criteria[i], "in the criteria's order")
		assert_eq(str(columns[3 + i]["type"]), "rating")
	assert_eq(StudyFormat.ratings_columns[0], "participant_id")
	assert_eq(StudyFormat.telemetry_columns.size(), 8)
	assert_eq(StudyFormat.telemetry_name("movement", 3), "telemetry/movement_3.csv")
	assert_eq(StudyFormat.telemetry_dir, "telemetry")
	assert_eq(StudyFormat.reserved_folders, PackedStringArray(["analysis"]))


func test_fields_are_checked_against_their_column() -> void:
	var by_name: Dictionary[String, Dictionary] = {}
	for column: Dictionary in StudyFormat.columns("ratings") + StudyFormat.columns("trials"):
		by_name[str(column["name"])] = column
	var cases: Array = [
		["ease", "10", ""],
		["ease", "11", "is not an integer 1-10"],
		["ease", "7.5", "is not an integer 1-10"],
		["order_index", "3", "is not an integer 0-2"],
		["condition", "haptic", "is unknown"],
		["condition", "constraint", ""],
		["time_to_goal_s", "-0.5", "is not a number >= 0"],
		["time_to_goal_s", "1.5e-3", ""],
		["wall_collisions", "2.0", "is not an integer >= 0"],
		["completed", "2", "is not an integer 0-1"],
		["timestamp", "yesterday", "is not a timestamp"],
		["level", "maze.v2", ""],
		["participant_id", "P 7", "is not a valid participant id"],
		["contact_model", "paper_sum", ""],
		["contact_model", "", ""],
		["contact_model", "sum", "is not empty or one of per_contact, paper_sum"],
	]
	for case: Array in cases:
		var column: Dictionary = by_name[str(case[0])]
		var what: String = "%s '%s'" % [case[0], case[1]]
		assert_eq(StudyFormat.field_problem(column, str(case[1])), str(case[2]), what)


func test_the_contact_models_are_the_renderers_names() -> void:
	var names: PackedStringArray = HapticsValue.choice_names(HapticMovementFacts.ContactModel)
	assert_eq(StudyFormat.contact_models, names)


func test_the_resume_scan_reads_records_by_column_name() -> void:
	var store: StudyStore = StudyStore.new(_root, "P07")
	assert_true(store.create(Support.meta("P07")), store.last_error)
	var ratings: String = StudyStore.native_path(store.path_of("ratings.csv"))
	var header: String = ",".join(StudyFormat.ratings_columns)
	var record: String = "P07,none,0,5,6,7,8,9,10,2025-05-01T10:00:00Z"
	var durable: DurableFile = DurableFile.new()
	durable.append(ratings, "%s\r\n%s\r\n" % [header, record])
	var state: ParticipantState = ParticipantState.scan(_root, "P07")
	assert_eq(state.problems, PackedStringArray(), "CRLF line ends are tolerated")
	assert_eq(state.rated.get("none", -1), 0, "rated in position 0")
	durable.append(ratings, 'P07,"movement",1,5,5,5,5,5,5,2025-05-01T10:01:00Z\n')
	state = ParticipantState.scan(_root, "P07")
	assert_has("\n".join(state.problems), "P07/ratings.csv:3: holds a quote")


func test_fractional_settings_are_read_by_name() -> void:
	var config: StudyConfig = StudyConfig.load_default()
	config.merge({"centre_tolerance": 0.2})
	assert_almost_eq(config.number("centre_tolerance"), 0.2, 1e-9)
	expect_error("not a fractional setting")
	assert_eq(config.number("trials_per_condition"), 0.0, "a whole-number setting is not one")
