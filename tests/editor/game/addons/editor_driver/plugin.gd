@tool
extends EditorPlugin
## The editor test's hands (tools/test-editor.sh). In one session of the GUI editor, on a
## project that has never seen the haptics addon, it does what a game developer does in their
## first hour: unpacks the addon zip into the project while the editor runs, lets the editor
## find it, enables the plugin, writes a script for the scene, creates a scene with a body and
## a HapticProbe made the way the Create dialog makes it, saves it, plays it (F6:
## play_current_scene) and waits for the game to end. One "editor-test:" line per step; a
## failed check prints "editor-test: FAIL ..." and the editor quits with 1.
##
## A step at a time from _process, its progress kept on the Engine: loading a new extension
## makes the editor reload every script, which cancels any coroutine waiting in this one.

enum Stage {
	FIRST_SCAN, ADDON_SCAN, ENABLED, CREATE_DIALOG, SCRIPT_SCAN, SCENE_OPEN, PLAYING, CLOSING, DONE
}

const ADDON_DIR := "res://addons/haptics"
const PLUGIN := "haptics"
const SCENE := "res://probe_scene.tscn"
const GAME_SCRIPT := "res://probe_check.gd"
## The developer's script for the scene, written once the plugin is enabled (it names the
## autoload and the probe's class).
const GAME_SCRIPT_SOURCE := "HAPTICS_EDITOR_TEST_SCRIPT"
const ADDON_ZIP := "HAPTICS_ADDON_ZIP"
const CLASSES: Array[String] = ["HapticProbe", "HapticMaterial", "HapticWater"]
## The start of HapticProbe's class description (its first ## line).
const PROBE_BRIEF := "Drop-in haptics for any 2D body"
const SETTINGS: Array[String] = [
	"haptics/input/hand_actions", "haptics/input/feed_actions", "haptics/servo/spin_us"
]
## Seconds each stage may take.
const STAGE_TIMEOUT_S := 120.0
## Seconds the editor may take to quit once asked, before a dialog it shows counts as asking.
const CLOSE_WAIT_S := 10.0
## Frames to let the editor settle after a stage's condition holds.
const SETTLE_FRAMES := 10
const STATE := &"editor_test_state"


func _enter_tree() -> void:
	if not Engine.has_meta(STATE):
		Engine.set_meta(STATE, {"stage": Stage.FIRST_SCAN, "since": _now(), "settle": 0})
		EditorInterface.get_resource_filesystem().filesystem_changed.connect(_on_filesystem_changed)


func _process(_delta: float) -> void:
	var state: Dictionary = Engine.get_meta(STATE, {})
	if state.is_empty() or state["stage"] == Stage.DONE:
		return
	if _now() - float(state["since"]) > STAGE_TIMEOUT_S:
		_check(false, "stage %s within %d s" % [Stage.keys()[state["stage"]], STAGE_TIMEOUT_S])
		_finish()
		return
	if not _ready_for(state):
		state["settle"] = 0
		return
	state["settle"] = int(state["settle"]) + 1
	if int(state["settle"]) < SETTLE_FRAMES or state.get("busy", false):
		return
	# Saving before play and opening a scene show progress, which runs frames (and so this)
	# inside the step.
	state["busy"] = true
	_advance(state)
	state["busy"] = false


# Whether the stage's wait is over.
func _ready_for(state: Dictionary) -> bool:
	var scanning: bool = EditorInterface.get_resource_filesystem().is_scanning()
	match state["stage"]:
		Stage.FIRST_SCAN, Stage.ENABLED, Stage.CREATE_DIALOG, Stage.SCENE_OPEN:
			return not scanning
		Stage.ADDON_SCAN, Stage.SCRIPT_SCAN:
			return state.get("changed", false) and not scanning
		Stage.CLOSING:
			return _now() - float(state["since"]) > CLOSE_WAIT_S
		Stage.PLAYING:
			# A short game may start and end between two of these frames' checks.
			if EditorInterface.is_playing_scene():
				state["played"] = true
			return state.get("played", false) and not EditorInterface.is_playing_scene()
	return false


func _advance(state: Dictionary) -> void:
	var waited: float = _now() - float(state["since"])
	match state["stage"]:
		Stage.FIRST_SCAN:
			var fresh: bool = not DirAccess.dir_exists_absolute(ADDON_DIR)
			_check(fresh, "the editor is open on a project without the addon")
			_unzip(OS.get_environment(ADDON_ZIP))
			_scan(state, Stage.ADDON_SCAN)
		Stage.ADDON_SCAN:
			_check(true, "the editor found the addon (%.1f s)" % waited)
			_check(ClassDB.class_exists(&"HapticsSystem"), "the extension loaded in this session")
			_check_global_classes()
			state["history"] = _global_history_version()
			_to(state, Stage.ENABLED)
			EditorInterface.set_plugin_enabled(PLUGIN, true)
		Stage.ENABLED:
			_check(EditorInterface.is_plugin_enabled(PLUGIN), "the plugin is enabled")
			_check(ProjectSettings.has_setting("autoload/Haptics"), "the Haptics autoload is set")
			_check(
				FileAccess.get_file_as_string("res://project.godot").contains("Haptics="),
				"the autoload is saved in project.godot (what F5/F6 read)"
			)
			# An action there is what quitting asks to "save modified resources" for.
			_check(
				_global_history_version() == state["history"],
				"enabling left nothing unsaved in the editor's undo history"
			)
			for setting: String in SETTINGS:
				_check(ProjectSettings.has_setting(setting), "Project Settings lists %s" % setting)
			_to(state, Stage.CREATE_DIALOG)
			EditorInterface.popup_create_dialog(_on_created, &"Node", "HapticProbe")
		Stage.CREATE_DIALOG:
			var shown: String = _create_dialog_description()
			_check(
				shown.contains(PROBE_BRIEF),
				"Create Node describes HapticProbe ('%s')" % shown.left(80).replace("\n", " ")
			)
			_write_game_script()
			_scan(state, Stage.SCRIPT_SCAN)
		Stage.SCRIPT_SCAN:
			_check(_save_probe_scene(), "a scene with a HapticProbe is made and saved")
			EditorInterface.open_scene_from_path(SCENE)
			_to(state, Stage.SCENE_OPEN)
		Stage.SCENE_OPEN:
			_to(state, Stage.PLAYING)
			_step("play the current scene (F6)")
			EditorInterface.play_current_scene()
		Stage.PLAYING:
			_check(true, "the game ran and ended by itself (%.1f s)" % waited)
			if _failed():
				_finish()
			else:
				_to(state, Stage.CLOSING)
				_step("close the editor's window")
				# What the window manager's close button sends the editor: it asks about anything
				# unsaved, or quits (with 0). Deferred: quitting frees this plugin.
				var editor_node: Node = EditorInterface.get_base_control().get_parent()
				editor_node.notification.call_deferred(NOTIFICATION_WM_CLOSE_REQUEST)
		Stage.CLOSING:
			_check(false, "the editor did not quit when asked; its windows: %s" % _dialogs())
			_finish()
	if _failed() and state["stage"] != Stage.DONE:
		_finish()


func _to(state: Dictionary, stage: Stage) -> void:
	state["stage"] = stage
	state["since"] = _now()
	state["settle"] = 0


# What the editor does when its window gets the focus back after files changed on the disk.
func _scan(state: Dictionary, stage: Stage) -> void:
	_to(state, stage)
	state["changed"] = false
	EditorInterface.get_resource_filesystem().scan()


func _on_filesystem_changed() -> void:
	var state: Dictionary = Engine.get_meta(STATE, {})
	state["changed"] = true


# Unpacks [param zip_path] into the project as a user's archive tool would.
func _unzip(zip_path: String) -> void:
	var reader: ZIPReader = ZIPReader.new()
	if reader.open(zip_path) != OK:
		_check(false, "open the addon zip '%s'" % zip_path)
		return
	var count: int = 0
	for entry: String in reader.get_files():
		var target: String = "res://".path_join(entry)
		DirAccess.make_dir_recursive_absolute(target.get_base_dir())
		if entry.ends_with("/"):
			continue
		var file: FileAccess = FileAccess.open(target, FileAccess.WRITE)
		file.store_buffer(reader.read_file(entry))
		file.close()
		count += 1
	reader.close()
	_step("unzipped %d files of %s" % [count, zip_path.get_file()])


# The node and resource types are in the Create dialogs: global classes with the addon's
# icons, and scripts that compile (a script that fails to parse cannot be created).
func _check_global_classes() -> void:
	var found: Dictionary[String, Dictionary] = {}
	for entry: Dictionary in ProjectSettings.get_global_class_list():
		found[str(entry["class"])] = entry
	for name: String in CLASSES:
		if not found.has(name):
			_check(false, "%s is a global class" % name)
			continue
		var entry: Dictionary = found[name]
		var icon: String = entry["icon"]
		_check(
			icon.begins_with(ADDON_DIR) and ResourceLoader.exists(icon),
			"%s is a global class with the addon's icon" % name
		)
		# A script that failed to parse has no base type: the Create dialog then reported
		# "Cannot get class ''".
		var script: Script = load(entry["path"]) as Script
		var base: StringName = script.get_instance_base_type() if script != null else &""
		_check(not base.is_empty(), "%s's script parses (a %s)" % [name, base])


func _write_game_script() -> void:
	var source: String = FileAccess.get_file_as_string(OS.get_environment(GAME_SCRIPT_SOURCE))
	_check(not source.is_empty(), "the scene's script is there to write")
	var file: FileAccess = FileAccess.open(GAME_SCRIPT, FileAccess.WRITE)
	file.store_string(source)
	file.close()


# What the Create dialog does for a script class: its native base with the script on it.
func _create(global_class: String) -> Node:
	for entry: Dictionary in ProjectSettings.get_global_class_list():
		if entry["class"] == global_class:
			var script: Script = load(entry["path"])
			var node: Node = ClassDB.instantiate(script.get_instance_base_type())
			node.set_script(script)
			node.name = global_class
			return node
	return null


func _save_probe_scene() -> bool:
	var probe: Node = _create("HapticProbe")
	if probe == null:
		return false
	var root: Node2D = Node2D.new()
	root.name = "Level"
	root.set_script(load(GAME_SCRIPT))
	var ground: StaticBody2D = StaticBody2D.new()
	ground.name = "Ground"
	ground.position = Vector2(320, 400)
	ground.add_child(_box(Vector2(600, 40)))
	var body: CharacterBody2D = CharacterBody2D.new()
	body.name = "Player"
	body.position = Vector2(320, 300)
	body.add_child(_box(Vector2(32, 48)))
	body.add_child(probe)
	root.add_child(ground)
	root.add_child(body)
	for node: Node in [ground, body, probe, ground.get_child(0), body.get_child(0)]:
		node.owner = root
	var packed: PackedScene = PackedScene.new()
	var saved: bool = packed.pack(root) == OK and ResourceSaver.save(packed, SCENE) == OK
	root.free()
	return saved


func _box(size: Vector2) -> CollisionShape2D:
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rectangle: RectangleShape2D = RectangleShape2D.new()
	rectangle.size = size
	shape.shape = rectangle
	return shape


func _global_history_version() -> int:
	var manager: EditorUndoRedoManager = EditorInterface.get_editor_undo_redo()
	return manager.get_history_undo_redo(EditorUndoRedoManager.GLOBAL_HISTORY).get_version()


func _on_created(_type: StringName) -> void:
	pass


# The description the Create dialog on screen shows for its selected type.
func _create_dialog_description() -> String:
	for dialog: Node in get_tree().root.find_children("*", "CreateDialog", true, false):
		var window: Window = dialog as Window
		if not window.visible:
			continue
		var text: String = ""
		for label: Node in window.find_children("*", "RichTextLabel", true, false):
			text += (label as RichTextLabel).get_parsed_text()
		window.hide()
		return text
	return "(no Create dialog shown)"


# The texts of the dialogs the editor shows now.
func _dialogs() -> PackedStringArray:
	var texts: PackedStringArray = []
	for window: Node in get_tree().root.find_children("*", "Window", true, false):
		var shown: Window = window as Window
		if not shown.visible:
			continue
		var accept: AcceptDialog = shown as AcceptDialog
		var text: String = accept.dialog_text.strip_edges() if accept != null else ""
		texts.append("%s '%s': %s" % [shown.get_class(), shown.title, text])
	return texts


func _finish() -> void:
	var state: Dictionary = Engine.get_meta(STATE, {})
	state["stage"] = Stage.DONE
	var code: int = 1 if _failed() else 0
	_step("quit (exit %d)" % code)
	get_tree().quit(code)


func _now() -> float:
	return Time.get_ticks_msec() / 1000.0


func _failed() -> bool:
	return Engine.get_meta(STATE, {}).get("failed", false)


func _step(text: String) -> void:
	print("editor-test: %s" % text)


func _check(ok: bool, what: String) -> void:
	_step(("ok: " if ok else "FAIL: ") + what)
	if not ok:
		Engine.get_meta(STATE, {})["failed"] = true
