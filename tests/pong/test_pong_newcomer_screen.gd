extends "res://tests/pong/pong_screen_suite.gd"
## What a newcomer sees and hears of Pong: the options come before the buttons that start a
## game, with the computer's difficulty (Easy by default) reaching the match; the status
## line names mines in words (never "none"); a ball resting against the near wall shows
## above the controls bar; bullets are red streaks along their flight, unlike the ball; and
## the match sounds its paddle contacts, bounces, bullets and mines with sounds made in
## code.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")


func test_the_options_come_before_the_start_buttons() -> void:
	_pong = PONG_SCENE.instantiate() as PongScreen
	add_child(_pong)
	await _setup_offered(_pong)
	var setup: PongSetup = _pong.setup
	var order: Array[Control] = [
		setup.difficulty_option,
		setup.beginner_check,
		setup.four_players_check,
		setup.vs_computer_button,
		setup.two_players_button,
		setup.demo_button,
	]
	for i: int in order.size() - 1:
		assert_true(
			_above(order[i], order[i + 1]), "%s above %s" % [order[i].name, order[i + 1].name]
		)
	assert_eq(setup.get_difficulty(), PongAiLevel.Level.EASY, "Easy by default")
	assert_eq(setup.difficulty_option.item_count, PongAiLevel.NAMES.size(), "every level")
	if not PongServo.shared().is_available():
		return
	setup.difficulty_option.select(PongAiLevel.Level.HARD)
	setup.vs_computer_button.pressed.emit()
	await wait_process_frames(1)
	var computer: PongAi = _pong.match_node.controllers[1] as PongAi
	var hard: Dictionary = PongAiLevel.KNOBS[PongAiLevel.Level.HARD]
	assert_eq(computer.fire_interval_s, hard["fire_interval_s"], "the chosen level plays")


func test_the_status_line_names_every_mine_in_words() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER)
	add_child(_pong)
	var match_node: PongMatch = _pong.match_node
	for kind: String in PongMines.KINDS:
		var mine: PongMines.Mine = PongMines.Mine.new(1, kind, Vector3(0.5, 0.0, 1.0))
		match_node.mine_exploded.emit(mine, 0)
		var text: String = _pong.hud.get_status_text()
		assert_false(text.contains(" none"), "no 'none' in '%s'" % text)
		assert_true(text.contains(PongMines.kind_name(kind)), "'%s' names the kind" % text)


func test_a_ball_resting_at_the_near_wall_shows_above_the_controls_bar() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER)
	add_child(_pong)
	await wait_process_frames(1)
	var court: PongCourt = _pong.match_node.court
	var camera: Camera3D = _pong.world.camera
	var size: Vector2 = camera.get_viewport().get_visible_rect().size
	var bar_top: float = _pong.hud.get_controls_rect().position.y
	var r: float = court.ball_radius
	for x: float in [0.0, -0.5 * court.half_width, 0.5 * court.half_width]:
		var resting: Vector3 = Vector3(x, r, court.half_length - r)
		var top_of_ball: Vector2 = camera.unproject_position(resting + Vector3.UP * r)
		var bottom: Vector2 = camera.unproject_position(resting - Vector3.UP * r)
		assert_true(bottom.y < bar_top, "the whole ball at x %.2f is above the bar" % x)
		assert_true(top_of_ball.y > 0.0 and top_of_ball.y < size.y, "and on the screen")
	# The far wall's top edge stays in view too.
	var far_top: Vector2 = camera.unproject_position(
		Vector3(0.0, court.wall_height, -court.half_length)
	)
	assert_true(far_top.y > 0.0, "the far wall's top is on the screen")


func test_bullets_are_streaks_along_their_flight_unlike_the_ball() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER)
	add_child(_pong)
	await wait_process_frames(1)
	var match_node: PongMatch = _pong.match_node
	var direction: Vector3 = Vector3(0.6, 0.0, -0.8)
	match_node.bullets.add(0, 0, Vector3(0.0, 1.0, 1.0), direction)
	_pong.world.render(match_node)
	var bullets: Node3D = _pong.world.get_node(^"Bullets")
	var streak: MeshInstance3D = bullets.get_child(0) as MeshInstance3D
	var capsule: CapsuleMesh = streak.mesh as CapsuleMesh
	if not assert_not_null(capsule, "a capsule, not a sphere"):
		return
	assert_gt(capsule.height, 4.0 * capsule.radius, "long and thin")
	var axis: Vector3 = streak.global_basis.y.normalized()
	assert_gt(axis.dot(direction.normalized()), 0.999, "along its flight")
	var ball: MeshInstance3D = _pong.world.get_node(^"Ball")
	var ball_colour: Color = (ball.get_active_material(0) as StandardMaterial3D).albedo_color
	var colour: Color = (capsule.material as StandardMaterial3D).albedo_color
	assert_gt(absf(colour.h - ball_colour.h) + absf(colour.s - ball_colour.s), 0.3, "its colour")


func test_the_match_sounds_contacts_bounces_bullets_and_mines() -> void:
	set_timeout(120.0)
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.DEMO, 2, 99, true)
	add_child(_pong)
	var heard: Dictionary[StringName, int] = {}
	_pong.sounds.played.connect(
		func(sound: StringName) -> void:
			var times: int = heard.get(sound, 0)
			heard[sound] = times + 1
	)
	var all: Callable = func() -> bool: return heard.size() == PongSounds.RECIPES.size()
	_pong.match_node.run_until(all, 90.0)
	print("    heard: %s" % heard)
	for sound: StringName in PongSounds.RECIPES:
		assert_gt(heard.get(sound, 0), 0, "%s is heard" % sound)
	assert_not_null(_pong.sounds.get_player(PongSounds.PADDLE).stream, "(a stream to play)")


func test_the_made_sounds_are_short_decaying_and_each_its_own() -> void:
	var rates: Dictionary[StringName, float] = {}
	for sound: StringName in PongSounds.RECIPES:
		var recipe: Dictionary = PongSounds.RECIPES[sound]
		var stream: AudioStreamWAV = PongSounds.make_stream(recipe, 1)
		var samples: PackedInt32Array = _samples(stream)
		var length_s: float = recipe["length_s"]
		assert_eq(samples.size(), roundi(length_s * PongSounds.MIX_RATE), "%s: its length" % sound)
		var peak: int = 0
		for value: int in samples:
			peak = maxi(peak, absi(value))
		var level: float = peak / 32767.0
		assert_true(level > PongSounds.PEAK * 0.5, "%s: loud enough (%.2f)" % [sound, level])
		assert_true(level <= PongSounds.PEAK + 1e-4, "%s: within its peak, never clipping" % sound)
		var quarter: int = floori(samples.size() * 0.25)
		assert_lt(
			_rms(samples, samples.size() - quarter, samples.size()),
			_rms(samples, 0, quarter) * 0.3,
			"%s: it fades" % sound
		)
		rates[sound] = _crossings(samples) / length_s
	# The tonal ones ring at their pitch: zero crossings twice per period, give or take.
	var paddle: Dictionary = PongSounds.RECIPES[PongSounds.PADDLE]
	var pitch: float = (paddle["from_hz"] + paddle["to_hz"]) * 0.5
	assert_almost_eq(rates[PongSounds.PADDLE], 2.0 * pitch, pitch * 0.5, "the paddle's pitch")
	# A bounce is lower (its noise adds crossings, so the margin is smaller than the pitches').
	assert_gt(rates[PongSounds.PADDLE], 1.3 * rates[PongSounds.BOUNCE], "a bounce is lower")


func _above(upper: Control, lower: Control) -> bool:
	return upper.get_global_rect().position.y < lower.get_global_rect().position.y


func _samples(stream: AudioStreamWAV) -> PackedInt32Array:
	var out: PackedInt32Array = PackedInt32Array()
	for i: int in floori(stream.data.size() * 0.5):
		out.append(stream.data.decode_s16(i * 2))
	return out


func _rms(samples: PackedInt32Array, from: int, to: int) -> float:
	var sum: float = 0.0
	for i: int in range(from, to):
		sum += float(samples[i]) * samples[i]
	return sqrt(sum / maxi(to - from, 1))


func _crossings(samples: PackedInt32Array) -> int:
	var count: int = 0
	for i: int in range(1, samples.size()):
		if (samples[i - 1] < 0) != (samples[i] < 0):
			count += 1
	return count
