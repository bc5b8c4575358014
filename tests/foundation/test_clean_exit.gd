extends TestSuite
## CleanExit (the autoload every quit goes through): it stops every sound, waits for the
## audio server to mix, and only then quits; the window's close button takes the same path.
## Each test uses its own instance with the quit replaced, so the run goes on. The windowed
## run that showed the leak is tools/test-windowed.sh (make test-windowed).

var _exit_codes: Array[int] = []


func before_each() -> void:
	_exit_codes.clear()


func after_each() -> void:
	get_tree().paused = false


func test_the_autoload_owns_the_close_button() -> void:
	assert_false(get_tree().auto_accept_quit, "CleanExit turned auto_accept_quit off")
	assert_false(CleanExit.is_quitting())


func test_stop_sounds_stops_every_kind_of_player_below_the_root() -> void:
	var root: Node2D = add_child_autofree(Node2D.new()) as Node2D
	var flat: AudioStreamPlayer = _player(AudioStreamPlayer.new(), root) as AudioStreamPlayer
	var positional: AudioStreamPlayer2D = (
		_player(AudioStreamPlayer2D.new(), root) as AudioStreamPlayer2D
	)
	var deep: Node3D = Node3D.new()
	root.add_child(deep)
	var spatial: AudioStreamPlayer3D = (
		_player(AudioStreamPlayer3D.new(), deep) as AudioStreamPlayer3D
	)
	var idle: AudioStreamPlayer = AudioStreamPlayer.new()
	root.add_child(idle)
	assert_true(flat.playing and positional.playing and spatial.playing, "all three play")
	assert_eq(GameExit.stop_sounds(root), 3, "three were playing, one was idle")
	assert_false(flat.playing)
	assert_false(positional.playing)
	assert_false(spatial.playing)
	assert_eq(GameExit.stop_sounds(root), 0, "nothing plays any more")


func test_quit_stops_sounds_and_waits_for_two_mixes_before_quitting() -> void:
	var exit: GameExit = _exit_under_test()
	var sound: AudioStreamPlayer = _player(AudioStreamPlayer.new(), self) as AudioStreamPlayer
	autofree(sound)
	var started_us: int = Time.get_ticks_usec()
	await exit.quit(7)
	assert_eq(_exit_codes, [7], "quit once, with the code asked for")
	assert_false(sound.playing, "the sound was stopped first")
	assert_true(get_tree().paused, "the tree was paused so no new sound starts")
	var since_mix_us: int = roundi(AudioServer.get_time_since_last_mix() * 1e6)
	assert_gt(
		Time.get_ticks_usec() - since_mix_us, started_us, "the audio server mixed after the stop"
	)


func test_a_second_quit_while_quitting_is_ignored() -> void:
	var exit: GameExit = _exit_under_test()
	exit.quit(1)
	assert_true(exit.is_quitting())
	await exit.quit(2)
	assert_true(await wait_until(func() -> bool: return not _exit_codes.is_empty(), 5.0))
	await wait_process_frames(2)
	assert_eq(_exit_codes, [1])


func test_the_close_button_quits_through_the_same_path() -> void:
	var exit: GameExit = _exit_under_test()
	exit.notification(NOTIFICATION_WM_CLOSE_REQUEST)
	assert_true(exit.is_quitting())
	assert_true(await wait_until(func() -> bool: return not _exit_codes.is_empty(), 5.0))
	assert_eq(_exit_codes, [0])


func test_alt_f4_that_reaches_the_game_as_keys_closes_it_and_f4_alone_does_not() -> void:
	var exit: GameExit = _exit_under_test()
	var f4: InputEventKey = InputEventKey.new()
	f4.keycode = KEY_F4
	f4.pressed = true
	exit._input(f4)
	assert_false(exit.is_quitting(), "F4 alone is the game's")
	f4.alt_pressed = true
	exit._input(f4)
	assert_true(exit.is_quitting(), "Alt+F4 no window manager took")
	assert_true(await wait_until(func() -> bool: return not _exit_codes.is_empty(), 5.0))
	assert_eq(_exit_codes, [0])


func test_the_wait_gives_up_after_its_limit() -> void:
	var exit: GameExit = _exit_under_test()
	# Asking for more mixes than can happen in 50 ms: it returns false, it does not hang.
	var saw_all: bool = await exit.wait_for_audio_mixes(1000, 0.05)
	assert_false(saw_all)


func _exit_under_test() -> GameExit:
	var exit: GameExit = add_child_autofree(GameExit.new()) as GameExit
	exit.quit_function = func(code: int) -> void: _exit_codes.append(code)
	return exit


## [param player] under [param parent], playing a short generated tone.
func _player(player: Node, parent: Node) -> Node:
	var tone: AudioStreamWAV = AudioStreamWAV.new()
	tone.format = AudioStreamWAV.FORMAT_8_BITS
	tone.mix_rate = 8000
	var samples: PackedByteArray = PackedByteArray()
	samples.resize(8000)
	for i: int in samples.size():
		samples[i] = 64 if (i >> 3) & 1 == 0 else 192
	tone.data = samples
	tone.loop_mode = AudioStreamWAV.LOOP_FORWARD
	tone.loop_end = samples.size()
	player.set(&"stream", tone)
	parent.add_child(player)
	player.call(&"play")
	return player
