class_name PracticeFlow
extends Node
## The practice before the maze trials: the demonstration levels under the practice
## conditions, cycled by the stage's Next level / Next method buttons, until the
## participant presses Ready. Nothing is recorded. The letters A, B, … name the conditions
## on screen, never their ids.

var _level_index: int = 0
var _condition_index: int = 0
# Whether the handle has been centred and the avatar moves.
var _live: bool = false

@onready var _runner: StudyRunner = get_parent() as StudyRunner


## Shows the first demonstration level under the first practice condition.
func start() -> void:
	var stage: StudyStage = _runner.use_stage()
	_level_index = 0
	_condition_index = 0
	stage.show_practice_controls(true)
	_runner.phase = StudyRunner.Phase.PRACTICE
	_load()


## One physics tick of practice: wait for the handle at the start, then let it move.
func tick(delta: float) -> void:
	var rig: ConditionRig = _runner.rig
	if not _live:
		if _runner.centre(delta):
			_live = true
			rig.go()
			_runner.get_stage().hide_card()
			_runner.get_stage().show_hand(Vector2.ZERO, false)
	elif _runner.autopilot and _runner.pilot != null:
		rig.set_hand(_runner.pilot.steer(rig, delta))


## The goal was reached in practice: cheer, put the avatar back, and arm the goal again.
func on_goal_reached() -> void:
	var stage: StudyStage = _runner.get_stage()
	stage.toast("Goal!")
	if not ConditionRig.is_position_control(_runner.rig.condition):
		_runner.rig.respawn()
	get_tree().create_timer(1.0).timeout.connect(_rearm_goal.bind(stage.level))


func on_next_level_pressed() -> void:
	if _runner.phase == StudyRunner.Phase.PRACTICE:
		_level_index += 1
		_load()


func on_next_condition_pressed() -> void:
	if _runner.phase == StudyRunner.Phase.PRACTICE:
		_condition_index += 1
		_load()


func on_ready_pressed() -> void:
	if _runner.phase == StudyRunner.Phase.PRACTICE:
		_runner.begin_condition(_runner.order_index)


func _load() -> void:
	var levels: PackedStringArray = _runner.config.demo_levels()
	var conditions: PackedStringArray = _runner.config.practice_conditions()
	if levels.is_empty() or conditions.is_empty():
		on_ready_pressed()
		return
	var scene: PackedScene = load(levels[_level_index % levels.size()]) as PackedScene
	var condition: String = conditions[_condition_index % conditions.size()]
	if not _runner.load_level(scene, condition):
		return
	_live = false
	_runner.show_centring()
	var stage: StudyStage = _runner.get_stage()
	var letter: String = char(65 + _condition_index % conditions.size())
	stage.set_status(
		"Practice: %s  ·  control %s of %d" % [stage.level.title, letter, conditions.size()],
		'Explore, bump into the walls, reach the flag. Press "I\'m ready" when comfortable.'
	)


func _rearm_goal(level: StudyLevel) -> void:
	if is_instance_valid(level):
		level.reset_goal()
