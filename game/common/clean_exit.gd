class_name GameExit
extends Node
## Quits the game without leaking (registered as the [code]CleanExit[/code] autoload).
##
## Godot's audio server drops a stopped or finished sound from its list only in its next mix
## step, and once quitting has begun no mix step runs: quitting while a sound plays leaks the
## stream and its playback ("ObjectDB instances leaked at exit", "3 resources still in use
## at exit"; godotengine/godot#76745). Headless runs play no sound, so only windowed runs
## showed it. Every quit of the game goes through [method quit]: it pauses the tree (no new
## sound starts), stops every player, waits until the audio server has mixed
## [constant MIXES_TO_WAIT] times, then quits. The window's close button comes here too
## ([member SceneTree.auto_accept_quit] is turned off).

## Mix steps to wait for after the sounds are stopped: the first may have begun before the
## stop, the second surely saw it.
const MIXES_TO_WAIT: int = 2
## Upper bound on that wait, in seconds (the Dummy driver mixes about every 90 ms); a machine
## whose audio thread never mixes still quits, after this long.
const MIX_WAIT_LIMIT_S: float = 1.0

## Frames after the window lost the focus or the pointer during which [method _process]
## checks whether another program destroyed it.
const GONE_CHECK_FRAMES: int = 30

## What quits once the sounds are gone; tests replace it.
var quit_function: Callable = _quit_tree

var _quitting: bool = false
var _gone_checks_left: int = 0


func _ready() -> void:
	get_tree().auto_accept_quit = false
	process_mode = Node.PROCESS_MODE_ALWAYS


func _notification(what: int) -> void:
	if what == NOTIFICATION_WM_CLOSE_REQUEST:
		# One line in the log: whether a close that seemed to do nothing ever reached the game.
		print("CleanExit: the window manager asked the game to close")
		quit(0)
	elif what == NOTIFICATION_WM_WINDOW_FOCUS_OUT or what == NOTIFICATION_WM_MOUSE_EXIT:
		_gone_checks_left = GONE_CHECK_FRAMES


# Alt+F4 is the desktop's close shortcut, which the window manager takes before the game
# sees it. When it reaches the game as keys, no window manager took it (the person suite saw
# a first press that never became a close request): the game closes, and says why.
func _input(event: InputEvent) -> void:
	var key: InputEventKey = event as InputEventKey
	if key != null and key.pressed and not key.echo and key.keycode == KEY_F4 and key.alt_pressed:
		print("CleanExit: Alt+F4 reached the game as keys (no window manager took it): closing")
		get_viewport().set_input_as_handled()
		quit(0)


# A window destroyed under the game (xdotool windowclose: no close request comes) left it
# running, each frame drawing into nothing with X errors, until the driver crashed: the
# focus and pointer leave it then, so a few frames after either ask X whether it is still
# there, and quit without drawing again if not.
func _process(_delta: float) -> void:
	if _gone_checks_left <= 0 or _quitting:
		return
	_gone_checks_left -= 1
	if window_gone():
		RenderingServer.render_loop_enabled = false
		quit(0)


## Whether the main window no longer exists (X11 only: another program destroyed it). X
## answers a query about a destroyed window with an error, which leaves the size unset.
static func window_gone() -> bool:
	if DisplayServer.get_name() != "X11":
		return false
	var outer: Vector2i = DisplayServer.window_get_size_with_decorations()
	var inner: Vector2i = DisplayServer.window_get_size()
	return outer.x < inner.x or outer.y < inner.y


## Whether [method quit] has been called (it runs over a few frames).
func is_quitting() -> bool:
	return _quitting


## Pauses the tree, stops every sound, waits for the audio server to let go of them, then
## quits with [param exit_code]. Later calls while quitting are ignored.
func quit(exit_code: int = 0) -> void:
	if _quitting:
		return
	_quitting = true
	get_tree().paused = true
	stop_sounds(get_tree().root)
	await wait_for_audio_mixes(MIXES_TO_WAIT, MIX_WAIT_LIMIT_S)
	quit_function.call(exit_code)


## Stops every [AudioStreamPlayer], [AudioStreamPlayer2D] and [AudioStreamPlayer3D] at or
## below [param root]; returns how many were playing.
static func stop_sounds(root: Node) -> int:
	var playing: int = 0
	var nodes: Array[Node] = [root]
	nodes.append_array(root.find_children("*", "", true, false))
	for node: Node in nodes:
		if node is AudioStreamPlayer:
			playing += 1 if (node as AudioStreamPlayer).playing else 0
			(node as AudioStreamPlayer).stop()
		elif node is AudioStreamPlayer2D:
			playing += 1 if (node as AudioStreamPlayer2D).playing else 0
			(node as AudioStreamPlayer2D).stop()
		elif node is AudioStreamPlayer3D:
			playing += 1 if (node as AudioStreamPlayer3D).playing else 0
			(node as AudioStreamPlayer3D).stop()
	return playing


## Waits until the audio server has begun [param count] mix steps after this call, or
## [param limit_s] seconds have passed; returns whether it saw them all.
func wait_for_audio_mixes(count: int, limit_s: float) -> bool:
	var start_us: int = Time.get_ticks_usec()
	var mark_us: int = start_us
	var seen: int = 0
	while seen < count:
		await get_tree().process_frame
		var now_us: int = Time.get_ticks_usec()
		if now_us - start_us > roundi(limit_s * 1e6):
			return false
		var last_mix_us: int = now_us - roundi(AudioServer.get_time_since_last_mix() * 1e6)
		if last_mix_us > mark_us:
			seen += 1
			mark_us = now_us
	return true


func _quit_tree(exit_code: int) -> void:
	# Debian's release template of Godot 4.6 fails two of the engine's own disconnects for every
	# container child that leaves, and the whole tree leaves at exit: a screenful of "Attempt
	# to disconnect a nonexistent connection ... callable: ''" after an autopilot run, none of
	# them ours (tools/bare/repro-disconnect.sh shows it with one script and no addon). A
	# release build says nothing more once its own exit work is done; debug builds (the tests,
	# the editor, the dedicated server) still print everything.
	if not OS.is_debug_build():
		Engine.print_error_messages = false
	get_tree().quit(exit_code)
