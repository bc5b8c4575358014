extends TestSuite
## Game code that reads [method Haptics.get_forces] once a frame: its [code]peak[/code] is
## the largest force of the frame's 1 kHz ticks, so no impact is missed; one tick's
## [code]total[/code], read once a frame, mostly shows a fraction of it.

const HARD := preload("res://addons/haptics/materials/hard.tres")
## Servo ticks per game frame (a 60 Hz game at 1 kHz).
const TICKS_PER_FRAME := 17

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))


func test_a_frame_read_of_the_peak_equals_the_1_khz_peak() -> void:
	var frame: HapticFrame = HapticFrame.new()
	var true_peak: float = 0.0
	var frame_peak: float = 0.0
	var frame_total: float = 0.0
	for game_frame: int in 12:
		frame.sequence = game_frame + 1
		door.submit_frame(frame)
		if game_frame == 4:
			door.push_impact(HapticProbe.impact_event(Vector2.UP, 2.86, HARD))
		for tick: int in TICKS_PER_FRAME:
			assert_true(HapticsTestKit.run(door, 1))
			true_peak = maxf(true_peak, door.get_forces().total.length())
		var forces: HapticForces = door.get_forces()
		frame_peak = maxf(frame_peak, forces.peak.length())
		frame_total = maxf(frame_total, forces.total.length())
	assert_gt(true_peak, 1.0, "the landing's impact")
	assert_almost_eq(frame_peak, true_peak, 0.05 * true_peak, "read once a frame: the same")
	assert_lt(frame_total, true_peak, "one tick's total read once a frame misses it")
