extends TestSuite
## The native extension as GDScript sees it: registration, both call paths, device list,
## and errors for bad calls that leave the game running.

const DEVICE_KEYS: Dictionary[String, int] = {
	"id": TYPE_STRING,
	"backend": TYPE_STRING,
	"vendor_id": TYPE_INT,
	"product_id": TYPE_INT,
	"path": TYPE_STRING,
	"product": TYPE_STRING,
	"manufacturer": TYPE_STRING,
	"serial": TYPE_STRING,
	"usage_page": TYPE_INT,
	"usage": TYPE_INT,
	"known_haptic": TYPE_BOOL,
	"model": TYPE_STRING,
}


func test_class_is_registered() -> void:
	assert_true(ClassDB.class_exists(&"HapticsServer"))
	assert_eq(ClassDB.get_parent_class(&"HapticsServer"), &"RefCounted")
	assert_true(ClassDB.class_has_method(&"HapticsServer", &"list_devices"))


func test_autoload_owns_a_server() -> void:
	assert_true(Haptics.is_available())
	assert_has(Haptics.get_version(), "haptics ")


func test_simulated_device_is_listed_first_with_documented_keys() -> void:
	var devices: Array = HapticsServer.new().list_devices()
	assert_gt(devices.size(), 0)
	var first: Dictionary = devices[0]
	for key: String in DEVICE_KEYS:
		assert_has(first, key)
		assert_eq(typeof(first[key]), DEVICE_KEYS[key], "type of '%s'" % key)
	assert_eq(first["id"], "simulated")
	assert_eq(first["backend"], "simulated")
	assert_true(first["known_haptic"])
	assert_has(first["model"], "Simulated")


func test_ids_are_unique() -> void:
	var seen: Dictionary[String, bool] = {}
	for device: Dictionary in Haptics.device.list_present():
		assert_false(seen.has(device["id"]), "duplicate id %s" % device["id"])
		seen[device["id"]] = true


func test_typed_ptrcall_and_untyped_call_agree() -> void:
	var typed: HapticsServer = HapticsServer.new()
	var untyped: Variant = HapticsServer.new()
	@warning_ignore("unsafe_method_access")
	assert_eq(typed.get_version(), untyped.get_version())
	var by_ptrcall: Dictionary = typed.get_device("simulated")
	@warning_ignore("unsafe_method_access")
	var by_call: Dictionary = untyped.get_device("simulated")
	assert_eq(by_ptrcall, by_call)
	assert_eq(by_ptrcall["model"], typed.list_devices()[0]["model"])


func test_too_many_arguments_is_a_call_error_and_the_game_goes_on() -> void:
	var server: HapticsServer = HapticsServer.new()
	expect_error("expected 0 argument(s), but called with 1")
	assert_null(server.callv(&"list_devices", [1]))
	assert_gt(server.list_devices().size(), 0, "the server still answers")


func test_too_few_arguments_is_a_call_error() -> void:
	var server: HapticsServer = HapticsServer.new()
	expect_error("expected 1 argument(s), but called with 0")
	assert_null(server.callv(&"get_device", []))


func test_wrong_argument_type_is_a_call_error() -> void:
	var server: HapticsServer = HapticsServer.new()
	expect_error("Cannot convert argument 1 from Array to String")
	assert_null(server.callv(&"get_device", [[1, 2]]))
	assert_eq(server.get_device("simulated")["id"], "simulated")


func test_unknown_device_id_reports_an_error_and_returns_empty() -> void:
	var server: HapticsServer = HapticsServer.new()
	expect_error("No device with id 'no-such-device'")
	assert_eq(server.get_device("no-such-device"), {})


func test_non_ascii_text_crosses_the_boundary_intact() -> void:
	var server: HapticsServer = HapticsServer.new()
	expect_error("No device with id 'Überhaptik ✓'")
	assert_eq(server.get_device("Überhaptik ✓"), {})


func test_enumeration_warnings_are_strings() -> void:
	var server: HapticsServer = HapticsServer.new()
	server.list_devices()
	for warning: Variant in server.get_device_warnings():
		assert_eq(typeof(warning), TYPE_STRING)
