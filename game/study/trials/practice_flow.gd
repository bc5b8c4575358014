class_name PracticeFlow
extends Node
## The practice before the maze trials: the demonstration levels under the practice
## conditions, cycled by the stage's Next level / Next method buttons, until the
## participant presses Ready. Nothing is recorded. The letters A, B, … name the conditions
## on screen, never their ids.

## The participant is ready (or there is nothing to practise): the trials may begin.
signal finished

var _context: StudyContext = null
var _level_index: int = 0
var _condition_index: int = 0
# Whether the handle has been centred and the avatar moves.
var _live: bool = false


## Hands the flow what it works with (before [method start]).
func setup(context: StudyContext) -> void:
	_context = context


## Shows the first demonstration level under the first practice condition (the stage is
## showing).
func start() -> void:
	_level_index = 0
	_condition_index = 0
	_context.stage.show_practice_controls(true)
	_context.session.phase = StudySession.Phase.PRACTICE
	_load()


## One physics tick of practice: wait for the handle at the start, then let it move.
func tick(delta: float) -> void:
	var rig: ConditionRig = _context.rig
	if not _live:
		if _context.centre(delta):
			_live = true
			rig.go()
			_context.stage.hide_card()
			_context.stage.show_hand(Vector2.ZERO, false)
	else:
		_context.steer(delta)


## The goal was reached in practice: cheer, put the avatar back, and arm the goal again.
func on_goal_reached() -> void:
	var stage: StudyStage = _context.stage
	stage.toast("Goal!")
	if not StudyFormat.is_position_control(_context.rig.condition):
		_context.rig.respawn()
	get_tree().create_timer(1.0).timeout.connect(_rearm_goal.bind(stage.level))


func on_next_level_pressed() -> void:
	if _practising():
		_level_index += 1
		_load()


func on_next_condition_pressed() -> void:
	if _practising():
		_condition_index += 1
		_load()


func on_ready_pressed() -> void:
	if _practising():
		finished.emit()


func _practising() -> bool:
	return _context.session.phase == StudySession.Phase.PRACTICE


func _load() -> void:
	var config: StudyConfig = _context.session.config
	var levels: PackedStringArray = config.demo_levels()
	var conditions: PackedStringArray = config.practice_conditions()
	if levels.is_empty() or conditions.is_empty():
		on_ready_pressed()
		return
	var scene: PackedScene = load(levels[_level_index % levels.size()]) as PackedScene
	var condition: String = conditions[_condition_index % conditions.size()]
	if not _context.load_level(scene, condition):
		return
	_live = false
	_context.show_centring()
	var stage: StudyStage = _context.stage
	var letter: String = char(65 + _condition_index % conditions.size())
	stage.set_status(
		"Practice: %s  ·  control %s of %d" % [stage.level.title, letter, conditions.size()],
		'Explore, bump into the walls, reach the flag. Press "I\'m ready" when comfortable.'
	)


func _rearm_goal(level: StudyLevel) -> void:
	if is_instance_valid(level):
		level.reset_goal()
