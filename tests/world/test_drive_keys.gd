extends TestSuite
## The drive scene driven with the arrow keys through the default door (without a device of
## their own, the keys move the simulated wheel): Up drives forward, Left turns the car left,
## the wheel comes back to the centre when the key is let go, and Down brakes it to a stop
## and then backs it slowly away, as a player at the menu's Drive without a wheel expects.

const SLOW := true
const DRIVE := preload("res://game/level3d/drive/drive.tscn")

## After this long on Up the car is well under way (m/s).
const UNDER_WAY_M_PER_S: float = 4.0
## Left held this long turns the car by at least this much (rad).
const LEFT_FRAMES: int = 40
const TURNED_LEAST_RAD: float = 0.1
## Let go, the front wheels are back within this of straight (rad) within a second.
const CENTRED_RAD: float = 0.03

## What a keyboard sends: key events, pressed and let go.
const KEYS: Array[Key] = [KEY_UP, KEY_LEFT, KEY_DOWN]


func after_each() -> void:
	for key: Key in KEYS:
		TestKeyboard.send(key, false)


func test_the_arrow_keys_drive_turn_and_brake_the_car() -> void:
	set_timeout(60.0)
	var scene: DriveScene = add_child_autofree(DRIVE.instantiate()) as DriveScene
	var car: DriveCar = scene.car
	var rate: int = Engine.physics_ticks_per_second
	await _frames(rate >> 1)  # Settled on its wheels: half a second.
	var by: String = "the device" if car.haptics.device_steers() else "the keys"

	TestKeyboard.send(KEY_UP, true)
	await _frames(rate * 2)
	var speed: float = car.forward_speed()
	assert_gt(speed, UNDER_WAY_M_PER_S, "Up for 2 s: %.1f m/s forward" % speed)

	var heading: Vector3 = car.global_basis.z
	TestKeyboard.send(KEY_LEFT, true)
	await _frames(LEFT_FRAMES)
	var steered: float = car.steering
	TestKeyboard.send(KEY_LEFT, false)
	var turned: float = heading.signed_angle_to(car.global_basis.z, Vector3.UP)
	assert_gt(steered, 0.1, "Left steers left (steering %.2f rad, by %s)" % [steered, by])
	assert_gt(turned, TURNED_LEAST_RAD, "and the car turned left: %.2f rad" % turned)

	var centred_after: int = -1
	for i: int in rate:
		await get_tree().physics_frame
		if absf(car.steering) < CENTRED_RAD:
			centred_after = i + 1
			break
	assert_gt(
		centred_after,
		0,
		"Left let go: the wheels back to straight within 1 s (%.2f)" % car.steering
	)

	TestKeyboard.send(KEY_UP, false)
	TestKeyboard.send(KEY_DOWN, true)
	var stopped_after: int = -1
	for i: int in rate * 4:
		await get_tree().physics_frame
		if car.forward_speed() < 0.5:
			stopped_after = i + 1
			break
	await _frames(rate * 3)  # Down still held: it backs away, slowly.
	var reverse: float = car.forward_speed()
	TestKeyboard.send(KEY_DOWN, false)
	print(
		(
			(
				"drive by keys (steered by %s): %.1f m/s after 2 s of Up; Left %d frames: steering "
				+ "%.2f rad, turned %.2f rad; centred %d frames after; Down stopped it in %d frames "
				+ "and backed it at %.1f m/s 3 s later"
			)
			% [by, speed, LEFT_FRAMES, steered, turned, centred_after, stopped_after, reverse]
		)
	)
	assert_gt(stopped_after, 0, "Down brakes it to a stop within 4 s")
	assert_lt(reverse, -1.0, "Down held on: the car reverses (%.1f m/s)" % reverse)
	assert_gt(reverse, -car.max_reverse_speed - 0.5, "no faster than its reverse speed")


func _frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
