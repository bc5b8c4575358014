extends TestSuite
## Every script a player or a developer gets (the addon and the games), and the drivers that
## run them in tests (the net suite's peers too, which only its processes load), compiles
## with the project's GDScript warnings raised to errors, the
## scene scripts too, which other suites may load before warnings are raised. project.godot
## makes an unsafe property or method access an error already, so a misspelt member of a
## typed value does not parse.

const FOLDERS: Array[String] = [
	"res://addons/haptics",
	"res://game",
	"res://tests/drivers",
	"res://tests/net/driver",
	"res://tests/net/rogue",
]


func test_every_product_script_compiles_without_warnings() -> void:
	var paths: PackedStringArray = PackedStringArray()
	for folder: String in FOLDERS:
		_collect(folder, paths)
	assert_gt(paths.size(), 100, "the scripts are found")
	var enabled: int = await assert_scripts_compile_without_warnings(paths)
	assert_gt(enabled, 0, "project.godot enables some GDScript warnings")


func test_a_misspelt_member_is_a_parse_error() -> void:
	for setting: String in ["unsafe_property_access", "unsafe_method_access"]:
		var level: int = ProjectSettings.get_setting("debug/gdscript/warnings/" + setting)
		assert_eq(level, 2, "%s is an error in project.godot" % setting)
	var script: GDScript = GDScript.new()
	script.source_code = (
		"extends RefCounted\n\n\nfunc touch(contact: HapticContact) -> void:\n"
		+ "\tcontact.normall = Vector2.UP\n"
	)
	expect_error('The property "normall" is not present')
	assert_ne(script.reload(), OK, "a misspelt property does not parse")


func _collect(folder: String, paths: PackedStringArray) -> void:
	for file: String in DirAccess.get_files_at(folder):
		if file.ends_with(".gd"):
			paths.append(folder.path_join(file))
	for sub: String in DirAccess.get_directories_at(folder):
		_collect(folder.path_join(sub), paths)
