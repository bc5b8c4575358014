extends TestSuite
## What the game-action suites share: a door of the test's own
## ([code]HapticsTestKit.manual()[/code]: the simulated device, no start-up ramp) that a probe
## talks to, run 1 ms tick by tick in step with the physics while [member recorder] keeps what
## the device received, and the impacts the probe reported.

const DeviceRecorder := preload("res://tests/world/device_recorder.gd")

var door: HapticsTestKit.Door = null
var recorder: DeviceRecorder = null
## Each impact the watched probe reported: [code]normal[/code], [code]speed[/code] (m/s).
var impacts: Array[Dictionary] = []


## Opens the door (call in before_each, before [method watch]); it is freed after the test.
func open_door() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))
	recorder = DeviceRecorder.new(door)
	impacts.clear()


## Points [param probe] at the door (before it enters the tree) and logs its impacts.
func watch(probe: HapticProbe) -> void:
	probe.haptics = door
	probe.impact.connect(_on_impact)


## Puts the simulated hand at [param normalized] times 10 cm (game axes).
func hand(normalized: Vector2) -> void:
	assert_true(HapticsTestKit.set_hand_m(door, normalized * 0.1))


## Waits [param count] physics frames, the servo running through each.
func run_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
		recorder.run(1.0 / Engine.physics_ticks_per_second)


func _on_impact(_collider: Object, normal: Vector2, speed: float) -> void:
	impacts.append({"normal": normal, "speed": speed})
