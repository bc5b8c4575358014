extends TestSuite
## What the game-action suites share: a [code]HapticsServer[/code] of the test's own (the
## simulated device, no start-up ramp) that a probe talks to, run 1 ms tick by tick in step
## with the physics while [member recorder] keeps what the device received, and the impacts
## the probe reported.

const DeviceRecorder := preload("res://tests/world/device_recorder.gd")

var server: HapticsServer = null
var recorder: DeviceRecorder = null
## Each impact the watched probe reported: [code]normal[/code], [code]speed[/code] (m/s).
var impacts: Array[Dictionary] = []


## Opens the server (call in before_each, before [method watch]).
func open_server() -> void:
	server = HapticsServer.new()
	assert_true(server.open_device("simulated"))
	assert_true(server.set_config("safety", {"startup_ramp_s": 0.0}))
	recorder = DeviceRecorder.new(server)
	impacts.clear()


## Points [param probe] at the server (before it enters the tree) and logs its impacts.
func watch(probe: HapticProbe) -> void:
	probe.server = server
	probe.impact.connect(_on_impact)


## Closes the server (call in after_each).
func close_server() -> void:
	server.close_device()


## Waits [param count] physics frames, the servo running through each.
func run_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
		recorder.run(1.0 / Engine.physics_ticks_per_second)


func _on_impact(_collider: Object, normal: Vector2, speed: float) -> void:
	impacts.append({"normal": normal, "speed": speed})
