@tool
extends EditorPlugin
## The addon's editor plugin: enabling it registers the [code]Haptics[/code] autoload and
## lists the native extension in [code].godot/extension_list.cfg[/code] (so the next start
## and import load it first); disabling it removes the autoload. While it is enabled the
## door's project settings ([code]haptics/input/*[/code], [code]haptics/servo/spin_us[/code])
## are listed in Project Settings ▸ Haptics with their defaults (and the spin's range). The
## node and resource types (HapticProbe, HapticMaterial, HapticWater) are global script
## classes: they are in the Create dialogs while the addon's folder is in the project.

const AUTOLOAD := "Haptics"
const EXTENSION_LIST := "res://.godot/extension_list.cfg"


# Every time the editor loads the plugin: the property types and defaults are not saved in
# project.godot, only values that differ from them.
func _enter_tree() -> void:
	var haptics: Script = load(_haptics_path()) as Script
	register_settings(haptics)
	# The servo's spin: its default and range are the native class's.
	haptics.call(&"add_project_settings")


func _enable_plugin() -> void:
	_set_autoload("*" + _haptics_path())
	list_extension(_addon_root().path_join("haptics.gdextension"))


func _disable_plugin() -> void:
	_set_autoload(null)
	unregister_settings(load(_haptics_path()) as Script)
	_save_project_settings()


## Adds [param extension] to the editor's extension list unless it is there; false when the
## list cannot be written.
static func list_extension(extension: String) -> bool:
	var listed: PackedStringArray = []
	if FileAccess.file_exists(EXTENSION_LIST):
		listed = FileAccess.get_file_as_string(EXTENSION_LIST).split("\n", false)
	if extension in listed:
		return true
	listed.append(extension)
	# A game fresh from its repository has no .godot folder yet.
	DirAccess.make_dir_recursive_absolute(EXTENSION_LIST.get_base_dir())
	var file: FileAccess = FileAccess.open(EXTENSION_LIST, FileAccess.WRITE)
	if file == null:
		push_error("Haptics: cannot write %s (%s)." % [EXTENSION_LIST, FileAccess.get_open_error()])
		return false
	file.store_string("\n".join(listed) + "\n")
	return true


## Lists the project settings [param haptics] (the door's script) reads in Project Settings,
## shown without Advanced Settings, with their types and defaults; one the project lacks is
## added at its default, a value it has is kept. False when [param haptics] names none.
static func register_settings(haptics: Script) -> bool:
	var settings: Dictionary = _settings_of(haptics)
	for setting: String in settings:
		var default: PackedStringArray = settings[setting]
		if not ProjectSettings.has_setting(setting):
			ProjectSettings.set_setting(setting, default)
		ProjectSettings.set_initial_value(setting, default)
		# Four input action names (left, right, up, down), each picked from the project's
		# actions or typed (an empty name is no action).
		(
			ProjectSettings
			. add_property_info(
				{
					"name": setting,
					"type": TYPE_PACKED_STRING_ARRAY,
					"hint": PROPERTY_HINT_TYPE_STRING,
					"hint_string": "%d/%d:loose_mode" % [TYPE_STRING, PROPERTY_HINT_INPUT_NAME],
				}
			)
		)
		ProjectSettings.set_as_basic(setting, true)
	return not settings.is_empty()


## Removes the settings of [param haptics] that hold their defaults (what
## [method register_settings] added); values the user changed stay in the project.
static func unregister_settings(haptics: Script) -> bool:
	var settings: Dictionary = _settings_of(haptics)
	for setting: String in settings:
		var value: Variant = ProjectSettings.get_setting(setting)
		if value is PackedStringArray and value == settings[setting]:
			ProjectSettings.set_setting(setting, null)
	return not settings.is_empty()


# The door's settings and their defaults (its SETTINGS constant).
static func _settings_of(haptics: Script) -> Dictionary:
	if haptics == null or not haptics.get_script_constant_map().get("SETTINGS") is Dictionary:
		var path: String = haptics.resource_path if haptics != null else "no script"
		push_error("Haptics: %s declares no SETTINGS; Project Settings left as they were." % path)
		return {}
	return haptics.get_script_constant_map()["SETTINGS"]


# Sets (or with null removes) the autoload and saves it at once. Not add_autoload_singleton:
# that is an action in the editor's undo history, so quitting asked to "save modified
# resources" when nothing had changed, Ctrl+Z took the autoload from an enabled plugin, and
# until something saved the project settings a game played with F5/F6 started without the
# autoload (the first script naming Haptics failed to parse there).
func _set_autoload(value: Variant) -> void:
	ProjectSettings.set_setting("autoload/" + AUTOLOAD, value)
	_save_project_settings()
	# The editor's list of autoloads, which also declares their names to the scripts it parses.
	var lists: Array[Node] = get_tree().root.find_children(
		"*", "EditorAutoloadSettings", true, false
	)
	for list: Node in lists:
		list.call(&"update_autoload")
	if lists.is_empty():
		push_warning("Haptics: restart the editor for scripts to see the Haptics autoload.")


func _save_project_settings() -> void:
	var error: Error = ProjectSettings.save()
	if error != OK:
		push_error("Haptics: cannot save the project settings (%s)." % error_string(error))


# The addon's folder (wherever it is): this script is in its editor/ folder.
func _addon_root() -> String:
	var script: Script = get_script()
	return script.resource_path.get_base_dir().get_base_dir()


# The door's script, in the addon's door/ folder.
func _haptics_path() -> String:
	return _addon_root().path_join("door/haptics.gd")
