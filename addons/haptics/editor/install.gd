extends SceneTree
## Enables the addon in a project without the editor (CI, a headless setup), as Project
## Settings ▸ Plugins ▸ Haptics does: the [code]Haptics[/code] autoload, the plugin in
## [code]editor_plugins[/code], the extension in [code].godot/extension_list.cfg[/code] (the
## folder made if the game has none yet). From the game's folder:
## [code]godot --headless --path . --script res://addons/haptics/editor/install.gd[/code].
## Running it again changes nothing.


func _init() -> void:
	var editor: String = (get_script() as Script).resource_path.get_base_dir()
	var plugin: Script = load(editor.path_join("plugin.gd")) as Script
	var addon: String = editor.get_base_dir()
	var autoload: String = "autoload/" + str(plugin.get_script_constant_map()["AUTOLOAD"])
	ProjectSettings.set_setting(autoload, "*" + addon.path_join("door/haptics.gd"))
	var enabled: PackedStringArray = ProjectSettings.get_setting(
		"editor_plugins/enabled", PackedStringArray()
	)
	if not addon.path_join("plugin.cfg") in enabled:
		enabled.append(addon.path_join("plugin.cfg"))
	ProjectSettings.set_setting("editor_plugins/enabled", enabled)
	var saved: Error = ProjectSettings.save()
	var listed: bool = plugin.call(&"list_extension", addon.path_join("haptics.gdextension"))
	if saved != OK or not listed:
		printerr("Haptics: not installed (project.godot: %s)." % error_string(saved))
		_skip_autoloads()
		quit(1)
		return
	_skip_autoloads()
	print(
		(
			"Haptics: enabled in %s (the autoload, the plugin, the extension listed)."
			% ProjectSettings.globalize_path("res://project.godot")
		)
	)
	quit(0)


# The engine starts the project's autoloads once this script's _init returns, and the game
# may not have been imported yet: without its class cache they fail to parse. Saved above,
# they are dropped from this run only.
func _skip_autoloads() -> void:
	for property: Dictionary in ProjectSettings.get_property_list():
		var setting: String = property["name"]
		if setting.begins_with("autoload/"):
			ProjectSettings.set_setting(setting, null)
