class_name PongAiLevel
extends RefCounted
## How hard the computer plays: the knobs of [PongAi] each difficulty level sets.
## [br]- EASY, the default against the computer, is a partner for a first-time player: it
## plays the ball back to the opponent's paddle (its workspace centre), gently, and its
## weapons come rarely and miss often. Its numbers were chosen with the scripted clumsy
## player of [code]tests/pong/test_pong_newcomer.gd[/code] (issue 25's note has the
## figures).
## [br]- NORMAL is [PongAi]'s defaults: it plays the ball deep into the opponent's half.
## [br]- HARD aims wider, reacts faster and shoots more.

enum Level { EASY, NORMAL, HARD }

## The names the game shows, one per [enum Level].
const NAMES: Array[String] = ["Easy", "Normal", "Hard"]
## Each level's knobs, members of [PongAi] by name; a knob a level leaves out keeps
## [PongAi]'s default.
const KNOBS: Array[Dictionary] = [
	{
		"plays_to_paddle": true,
		"aim_error_m": 0.12,
		"shot_speed_m_per_s": 2.8,
		"fire_interval_s": 8.0,
		"gun_error_rad": 0.3,
		"mine_rate_per_s": 0.03,
	},
	{},
	{
		"reaction_delay_s": 0.08,
		"aim_error_m": 0.5,
		"shot_speed_m_per_s": 4.5,
		"fire_interval_s": 1.6,
		"gun_error_rad": 0.05,
		"mine_rate_per_s": 0.15,
	},
]


## Sets [param ai]'s knobs for [param level] (a [enum Level]).
static func apply(ai: PongAi, level: int) -> void:
	var knobs: Dictionary = KNOBS[level]
	for knob: String in knobs:
		ai.set(knob, knobs[knob])
