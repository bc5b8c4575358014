class_name StudyLaunch
extends RefCounted
## What the study needs before its first screen: the command line (when the study scene
## runs on its own), the settings in their layers, whether the study can run here at all,
## and the consent text. Run on its own, the scene reads these arguments after
## [code]--[/code]:
## [codeblock]
## --study-root=PATH          study folder (default: the config's, user://study)
## --study-config=PATH        extra settings file merged over the defaults
## [/codeblock]
## (A scripted participant plays the study from [code]tests/drivers/study_scripted.tscn[/code],
## which takes these too.)

## The consent text shipped with the game; a [code]consent.txt[/code] in the study folder
## replaces it.
const DEFAULT_CONSENT_PATH: String = "res://assets/study/consent.txt"


## The [StudyRunner] properties the command line sets: property name → value.
static func command_line() -> Dictionary:
	var out: Dictionary = {}
	for arg: String in OS.get_cmdline_user_args():
		var value: String = arg.get_slice("=", 1) if arg.contains("=") else ""
		if arg.begins_with("--study-root="):
			out["study_root"] = value
		elif arg.begins_with("--study-config="):
			out["config_path"] = value
	return out


## The settings: the shipped ones, then [param config_path] (if any), then
## [param study_root] (if any), then the study folder's own file, which may not move the
## study folder.
static func load_config(config_path: String, study_root: String) -> StudyConfig:
	var loaded: StudyConfig = StudyConfig.load_default()
	if not config_path.is_empty():
		loaded.merge_file(config_path)
	if not study_root.is_empty():
		loaded.merge({"study_root": study_root}, "--study-root")
	var root: String = loaded.study_root()
	loaded.merge_file(root.path_join(StudyConfig.ROOT_FILE), true)
	if loaded.study_root() != root:
		loaded.errors.append(
			"%s: 'study_root' cannot be changed from inside the study folder" % root
		)
	return loaded


## Why the study cannot run here (one reason a line), or "".
static func refusal(config: StudyConfig) -> String:
	var lines: PackedStringArray = PackedStringArray()
	for error: String in config.errors:
		lines.append("Study settings: " + error)
	if not StudyStore.is_available():
		lines.append(
			(
				"The haptics extension (DurableFile) is not loaded, so study data cannot be "
				+ "saved safely. Build it with 'make build' and restart."
			)
		)
	elif not Haptics.servo.is_running():
		lines.append("The haptic device is not running: check the device in Settings.")
	return "\n".join(lines)


## The consent text and where it came from: the study folder's, else the shipped one.
static func consent(config: StudyConfig) -> PackedStringArray:
	var own: String = config.study_root().path_join("consent.txt")
	for path: String in [own, DEFAULT_CONSENT_PATH]:
		if FileAccess.file_exists(path):
			return PackedStringArray([FileAccess.get_file_as_string(path), path])
	return PackedStringArray(["(No consent text: add %s.)" % own, own])


## The game's version for participant.json ("dev" when the project sets none).
static func app_version() -> String:
	var version: String = str(ProjectSettings.get_setting("application/config/version", ""))
	return version if not version.is_empty() else "dev"
