class_name StudyParticipant
extends Node
## Who takes part in the study, as the [StudyRunner] sees them: this base class is a person at
## the real screens and the device, so it does nothing itself (the screens wait for their
## buttons; the hand is the device's, or the simulated one's that the mouse and keys move).
## [br][br]
## The runner adds it as its child, hands it the session ([method join]), tells it every
## screen it shows ([method show_screen]) and every level it sets up ([method start_level]),
## and, when it [method steers_hand], asks it at every physics tick where the hand goes
## ([method steer]). Test drivers ([code]tests/drivers/[/code]) extend it to play whole
## sessions unattended.


## The session it takes part in, before the first screen shows.
func join(_session: StudySession) -> void:
	pass


## The runner shows [param _screen] now.
func show_screen(_screen: Control) -> void:
	pass


## Whether it moves the (simulated) hand itself through [method steer], rather than a person
## moving the device, the mouse or the keys.
func steers_hand() -> bool:
	return false


## [param _rig] has set a level up under its condition, the avatar at the start;
## [param _trial]: a recorded trial begins now (else a practice level, or the maze before
## its trial).
func start_level(_rig: ConditionRig, _trial: bool) -> void:
	pass


## Where the hand goes this physics tick (normalised, game axes) while the avatar may move;
## asked only when it [method steers_hand].
func steer(rig: ConditionRig, _delta: float) -> Vector2:
	return rig.start_hand()
