extends RefCounted
## Finds the test scripts: test_*.gd files below a folder, sorted, skipping the fixtures and
## the runner unless the search starts there, and folders with a .gdignore.

## Folders skipped unless the search starts inside them.
const EXCLUDED_DIRS: PackedStringArray = ["res://tests/fixtures", "res://tests/runner"]
## Folders never searched (the runner's own files are named test_*.gd).
const NEVER_SEARCHED: PackedStringArray = ["res://tests/runner"]


## Every test_*.gd below [param root] (or [param root] itself if it is a file), sorted.
static func discover(root: String) -> PackedStringArray:
	var found: PackedStringArray = PackedStringArray()
	if FileAccess.file_exists(root):
		found.append(root)
	else:
		_walk(root, root, found)
	return found


static func _walk(dir_path: String, root: String, found: PackedStringArray) -> void:
	var dir: DirAccess = DirAccess.open(dir_path)
	if dir == null:
		return
	var files: PackedStringArray = dir.get_files()
	files.sort()
	for file_name: String in files:
		if file_name.begins_with("test_") and file_name.ends_with(".gd"):
			found.append(dir_path.path_join(file_name))
	var subdirs: PackedStringArray = dir.get_directories()
	subdirs.sort()
	for subdir: String in subdirs:
		var sub_path: String = dir_path.path_join(subdir)
		if (
			not _is_excluded(sub_path, root)
			and not FileAccess.file_exists(sub_path.path_join(".gdignore"))
		):
			_walk(sub_path, root, found)


static func _is_excluded(dir_path: String, root: String) -> bool:
	if dir_path in NEVER_SEARCHED:
		return true
	for excluded: String in EXCLUDED_DIRS:
		if dir_path == excluded and root != excluded and not root.begins_with(excluded + "/"):
			return true
	return false
