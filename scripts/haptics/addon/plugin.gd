@tool
extends EditorPlugin
## The addon's editor plugin: enabling it registers the [code]Haptics[/code] autoload and
## lists the native extension in [code].godot/extension_list.cfg[/code] (so the next start
## and import load it first); disabling it removes the autoload. The node and resource
## types (HapticProbe, HapticMaterial, HapticWater) are global script classes: they are in
## the Create dialogs while the addon's folder is in the project. While it is enabled, the
## Project Settings dialog lists the settings the autoload reads (haptics/servo/spin_us) with
## their defaults and ranges.

const AUTOLOAD := "Haptics"
const EXTENSION_LIST := "res://.godot/extension_list.cfg"


func _enter_tree() -> void:
	# Property hints are not saved with the project: they are added in every editor session.
	var folder: String = (get_script() as Script).resource_path.get_base_dir()
	load(folder.path_join("haptics.gd")).call(&"add_project_settings")


func _enable_plugin() -> void:
	var folder: String = (get_script() as Script).resource_path.get_base_dir()
	add_autoload_singleton(AUTOLOAD, folder.path_join("haptics.gd"))
	list_extension(folder.path_join("haptics.gdextension"))


func _disable_plugin() -> void:
	remove_autoload_singleton(AUTOLOAD)


## Adds [param extension] to the editor's extension list unless it is there; false when the
## list cannot be written.
static func list_extension(extension: String) -> bool:
	var listed: PackedStringArray = []
	if FileAccess.file_exists(EXTENSION_LIST):
		listed = FileAccess.get_file_as_string(EXTENSION_LIST).split("\n", false)
	if extension in listed:
		return true
	listed.append(extension)
	var file: FileAccess = FileAccess.open(EXTENSION_LIST, FileAccess.WRITE)
	if file == null:
		push_error("Haptics: cannot write %s (%s)." % [EXTENSION_LIST, FileAccess.get_open_error()])
		return false
	file.store_string("\n".join(listed) + "\n")
	return true
