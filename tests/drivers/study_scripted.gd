extends Node
## The maze study played unattended by a [ScriptedParticipant]: the real study scene
## (game/study/session/study.tscn) with the scripted participant in the person's place, for a
## demo dataset and the study's process tests. After [code]--[/code]:
## [codeblock]
## --study-root=PATH          study folder (as the study scene's own option)
## --study-config=PATH        extra settings file merged over the defaults (as its own)
## --scripted-participant=ID  the participant's id (default SCRIPTED)
## --resume                   resume ID instead of starting it
## --hold=SECONDS             keep still this long at the start of each trial
## --touch-walls              push into (and through) the walls around the start first
## --quit-when-done           quit when the session ends (exit code 0)
## [/codeblock]
## [codeblock]
## tools/godot --headless --path . res://tests/drivers/study_scripted.tscn -- \
##     --study-root=/tmp/demo_study --scripted-participant=P01 --quit-when-done
## [/codeblock]

const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")


func _ready() -> void:
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	var arguments: Dictionary = StudyLaunch.command_line()
	for property: String in arguments:
		study.set(property, arguments[property])
	var participant: ScriptedParticipant = ScriptedParticipant.new()
	var quit_when_done: bool = false
	for arg: String in OS.get_cmdline_user_args():
		var value: String = arg.get_slice("=", 1) if arg.contains("=") else ""
		if arg.begins_with("--scripted-participant="):
			participant.participant_id = value
		elif arg == "--resume":
			participant.resume = true
		elif arg.begins_with("--hold="):
			participant.hold_s = value.to_float()
		elif arg == "--touch-walls":
			participant.touch_walls = true
		elif arg == "--quit-when-done":
			quit_when_done = true
	participant.take_part_in(study)
	if quit_when_done:
		participant.finished.connect(_quit)
	study.closed.connect(_quit)
	add_child(study)


func _quit() -> void:
	CleanExit.quit(0)
