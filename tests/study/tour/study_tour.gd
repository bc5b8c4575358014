extends Node
## Walks through the study's screens under a real display and saves a PNG of each, for
## looking at them (not a test: the runner only runs test_*.gd files).
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/study/tour/study_tour.tscn -- --out=/tmp/study_shots [--maze=res://...]
## [/codeblock]
## With [code]--menu[/code] it shows the way in from the title screen instead.
## The data goes to a fresh folder under user://study_tour/, never to the real study.

const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")
const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")

var _out: String = "user://study_shots"
var _maze: String = ""


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--out="):
			_out = arg.get_slice("=", 1)
		elif arg.begins_with("--maze="):
			_maze = arg.get_slice("=", 1)
	DirAccess.make_dir_recursive_absolute(_out)
	if OS.get_cmdline_user_args().has("--menu"):
		_menu_tour.call_deferred()
	else:
		_tour.call_deferred()


# The way in from the title screen and back.
func _menu_tour() -> void:
	var main: Main = MAIN_SCENE.instantiate() as Main
	main.read_command_line = false
	add_child(main)
	await _shot("menu", 0.8)
	var menu: MainMenu = main.get_screen() as MainMenu
	menu.maze_button.pressed.emit()
	await _shot("menu_study", 0.8)
	var study: StudyRunner = main.get_screen() as StudyRunner
	(study.get_screen() as StartScreen).back_button.pressed.emit()
	await _shot("menu_back", 0.6)
	get_tree().quit(0)


func _tour() -> void:
	var root: String = "user://study_tour/%d" % Time.get_ticks_usec()
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = root
	# The tour answers the screens itself; the scripted participant only steers the hand.
	var hand: ScriptedParticipant = ScriptedParticipant.new()
	hand.plays_screens = false
	study.participant = hand
	add_child(study)
	await _shot("start_empty", 0.6)
	var start: StartScreen = study.get_screen() as StartScreen
	start.id_edit.text = "P01"
	start.set_demographic("age_band", "30-39")
	start.set_demographic("gender", "female")
	start.set_demographic("handedness", "right")
	start.set_demographic("hand_used", "left")
	start.set_demographic("gaming_experience", "little")
	start.start_button.pressed.emit()
	await _shot("start_refused", 0.4)
	start.consent_check.button_pressed = true
	if not _maze.is_empty():
		study.config.merge({"maze_level": _maze})
	start.start_button.pressed.emit()
	await _shot("practice_open", 1.5)
	study.get_stage().next_condition_pressed.emit()
	await _shot("practice_open_constraint", 1.5)
	study.get_stage().next_level_pressed.emit()
	await _shot("practice_corridors", 1.5)
	study.get_stage().ready_pressed.emit()
	await _shot("intro", 0.6)
	study.get_stage().start_pressed.emit()
	for i: int in 3:
		await _shot("centring_%d_%s" % [i, study.current_condition()], 0.15)
		await _wait_phase(study, StudySession.Phase.TRIAL)
		await _shot("trial_%d_%s" % [i, study.current_condition()], 2.0)
		await _wait_phase(study, StudySession.Phase.RATING)
		var rating: RatingScreen = study.get_screen() as RatingScreen
		for criterion: String in ["realism", "ease", "aptness"]:
			rating.set_rating(criterion, 7)
		await _shot("rating_%d_partial" % i, 0.3)
		for criterion: String in StudyFormat.criteria:
			rating.set_rating(criterion, 3 + i * 3)
		rating.submit_button.pressed.emit()
		if i < 2:
			await _wait_phase(study, StudySession.Phase.INTRO)
			study.get_stage().start_pressed.emit()
	await _wait_phase(study, StudySession.Phase.FINAL)
	var final: FinalScreen = study.get_screen() as FinalScreen
	final.text_edit.text = "The second one pushed back when I hit a wall."
	final.set_favourite(PackedInt32Array([1, 2]))
	await _shot("final", 0.4)
	final.submit_button.pressed.emit()
	await _shot("done", 0.4)
	get_tree().quit(0)


func _wait_phase(study: StudyRunner, phase: StudySession.Phase) -> void:
	var deadline: int = Time.get_ticks_msec() + 60000
	while study.phase != phase and Time.get_ticks_msec() < deadline:
		await get_tree().process_frame


func _shot(shot_name: String, wait_seconds: float) -> void:
	await get_tree().create_timer(wait_seconds).timeout
	await RenderingServer.frame_post_draw
	var image: Image = get_viewport().get_texture().get_image()
	image.save_png(_out.path_join(shot_name + ".png"))
	print("saved ", _out.path_join(shot_name + ".png"))
