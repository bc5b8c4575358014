extends TestSuite
## Every Pong script compiles with the project's GDScript warnings raised to errors (the
## scene scripts too, which other suites may load before warnings are raised).

const FOLDERS: Array[String] = ["res://game/pong"]
const FILES: Array[String] = []


func test_every_pong_script_compiles_without_warnings() -> void:
	var paths: PackedStringArray = PackedStringArray(FILES)
	for folder: String in FOLDERS:
		_collect(folder, paths)
	assert_gt(paths.size(), 10, "the Pong scripts are found")
	var enabled: int = await assert_scripts_compile_without_warnings(paths)
	assert_gt(enabled, 0, "project.godot enables some GDScript warnings")


func _collect(folder: String, paths: PackedStringArray) -> void:
	for file: String in DirAccess.get_files_at(folder):
		if file.ends_with(".gd"):
			paths.append(folder.path_join(file))
	for sub: String in DirAccess.get_directories_at(folder):
		_collect(folder.path_join(sub), paths)
