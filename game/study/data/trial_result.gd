class_name TrialResult
extends RefCounted
## The measures of one maze trial: one trials.csv record (FORMAT.md) before it is written.

## [code]none[/code], [code]movement[/code] or [code]constraint[/code].
var condition: String = ""
## Level id, e.g. [code]maze[/code].
var level: String = ""
## This participant's trial count in this condition (from 0, never reused).
var trial_index: int = 0
## The movement renderer's contact model during the trial ([code]per_contact[/code] or
## [code]paper_sum[/code]); empty in position control.
var contact_model: String = ""
## Seconds from the start to the goal (or to the end of an unfinished trial).
var time_s: float = 0.0
## Whether the goal was reached.
var completed: bool = false
## Distinct wall contacts (contact onsets).
var wall_collisions: int = 0
## Total time touching a wall, seconds.
var contact_time_s: float = 0.0
## Distance the avatar travelled, level pixels.
var path_length_px: float = 0.0
## Time-averaged magnitude of the rendered force, newtons.
var mean_force_n: float = 0.0
## Largest rendered force magnitude, newtons.
var max_force_n: float = 0.0
## The telemetry file relative to the participant folder, or empty.
var telemetry_file: String = ""
