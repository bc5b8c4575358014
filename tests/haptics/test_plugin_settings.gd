extends TestSuite
## The addon's plugin and the door's project settings: enabling the plugin lists
## haptics/input/* in Project Settings (type, hint, default, shown without Advanced
## Settings) and keeps values the project has; disabling removes what holds its default and
## keeps what the user changed. Nothing here saves project.godot.

const PLUGIN := "res://addons/haptics/editor/plugin.gd"
const HAPTICS := "res://addons/haptics/door/haptics.gd"

var plugin: Script = null
var haptics: Script = null
var _saved: Dictionary = {}


func before_each() -> void:
	plugin = load(PLUGIN)
	haptics = load(HAPTICS)
	_saved.clear()
	for setting: String in Haptics.SETTINGS:
		if ProjectSettings.has_setting(setting):
			_saved[setting] = ProjectSettings.get_setting(setting)
		ProjectSettings.set_setting(setting, null)


func after_each() -> void:
	for setting: String in Haptics.SETTINGS:
		ProjectSettings.set_setting(setting, _saved.get(setting))


func _property(setting: String) -> Dictionary:
	for property: Dictionary in ProjectSettings.get_property_list():
		if property["name"] == setting:
			return property
	return {}


func test_enabling_lists_each_input_setting_with_its_type_and_default() -> void:
	assert_eq(Haptics.SETTINGS.size(), 2, "hand_actions and feed_actions")
	assert_true(plugin.call(&"register_settings", haptics))
	for setting: String in Haptics.SETTINGS:
		var default: PackedStringArray = Haptics.SETTINGS[setting]
		assert_true(ProjectSettings.has_setting(setting), setting)
		assert_eq(ProjectSettings.get_setting(setting), default, setting + " at its default")
		assert_eq(ProjectSettings.property_get_revert(setting), default, setting + " reverts")
		var property: Dictionary = _property(setting)
		assert_eq(property.get("type"), TYPE_PACKED_STRING_ARRAY, setting + " type")
		assert_eq(property.get("hint"), PROPERTY_HINT_TYPE_STRING, setting + " hint")
		assert_eq(
			property.get("hint_string"),
			"%d/%d:loose_mode" % [TYPE_STRING, PROPERTY_HINT_INPUT_NAME],
			setting + ": action names"
		)
		var usage: int = property.get("usage", 0)
		assert_ne(usage & PROPERTY_USAGE_EDITOR_BASIC_SETTING, 0, setting + " shown as basic")
	assert_eq(
		ProjectSettings.get_setting(Haptics.SETTING_HAND_ACTIONS),
		PackedStringArray(["ui_left", "ui_right", "ui_up", "ui_down"]),
		"the hand's default actions: Godot's own, in every project"
	)
	assert_eq(ProjectSettings.get_setting(Haptics.SETTING_FEED_ACTIONS), PackedStringArray())


func test_enabling_keeps_a_value_the_project_has() -> void:
	var own: PackedStringArray = ["left", "right", "", ""]
	ProjectSettings.set_setting(Haptics.SETTING_FEED_ACTIONS, own)
	assert_true(plugin.call(&"register_settings", haptics))
	assert_eq(ProjectSettings.get_setting(Haptics.SETTING_FEED_ACTIONS), own, "kept")
	assert_eq(
		ProjectSettings.property_get_revert(Haptics.SETTING_FEED_ACTIONS),
		Haptics.DEFAULT_FEED_ACTIONS,
		"reverts to the default"
	)


func test_disabling_removes_the_defaults_and_keeps_what_the_user_changed() -> void:
	assert_true(plugin.call(&"register_settings", haptics))
	var own: PackedStringArray = ["left", "right", "", ""]
	ProjectSettings.set_setting(Haptics.SETTING_FEED_ACTIONS, own)
	assert_true(plugin.call(&"unregister_settings", haptics))
	assert_false(ProjectSettings.has_setting(Haptics.SETTING_HAND_ACTIONS), "default: removed")
	assert_eq(ProjectSettings.get_setting(Haptics.SETTING_FEED_ACTIONS), own, "changed: kept")


func test_a_script_without_settings_is_refused_and_changes_nothing() -> void:
	expect_error("declares no SETTINGS")
	assert_false(plugin.call(&"register_settings", plugin))
	for setting: String in Haptics.SETTINGS:
		assert_false(ProjectSettings.has_setting(setting), setting + " not added")
