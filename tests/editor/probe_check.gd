extends Node2D
## The played scene's own script, as a developer trying the addon would write it (the editor
## test writes it into the project once the plugin is enabled): the player falls onto the
## ground, and once it has stood there, with the hand held pressing down, the servo must push
## the hand back up out of the floor. Prints one "probe-check:" line and quits with 0, or 1
## when it did not.

const FRAMES := 90
const MIN_PUSH_N := 0.1

var _frame: int = 0


func _ready() -> void:
	# The hand held pressing down, as a player leaning on the floor.
	Haptics.hand_follows_input = false
	Haptics.device.set_hand_target(Vector2.DOWN * 0.5)


func _physics_process(delta: float) -> void:
	var player: CharacterBody2D = $Player
	player.velocity += player.get_gravity() * delta
	player.move_and_slide()
	_frame += 1
	if _frame < FRAMES:
		return
	var push: Vector2 = Haptics.get_forces().parts[HapticMovementFacts.MovementForce.NORMAL]
	var probe: HapticProbe = $Player/HapticProbe
	var ok: bool = Haptics.is_available() and push.y < -MIN_PUSH_N
	print(
		(
			"probe-check: %s: %s, %d frames sent, push %s N"
			% ["ok" if ok else "FAIL", Haptics.get_version(), probe.frames_submitted, push]
		)
	)
	get_tree().quit(0 if ok else 1)
