extends "res://tests/haptics/test_haptic_water.gd"
## The game's water is the addon's [HapticWater]: every test of the addon's water runs again
## here on a [WaterVolume] (with the layers of the game's water scene), and then what the
## game adds: a floating crate carries its lift ([member Crate.buoyancy], which the player's
## felt weight uses), a frozen crate gets none, and a crate that leaves is dry.

const CRATE := preload("res://game/props/crate.tscn")
const WATER_SCENE := preload("res://game/props/water.tscn")


func _make_water() -> HapticWater:
	var volume: WaterVolume = WaterVolume.new()
	var scene_water: WaterVolume = WATER_SCENE.instantiate() as WaterVolume
	volume.collision_layer = scene_water.collision_layer
	# The game's props and player, and layer 1 that the addon's tests use.
	volume.collision_mask = scene_water.collision_mask | 1
	scene_water.free()
	return volume


func _game_crate(x: float, y: float) -> Crate:
	var crate: Crate = CRATE.instantiate() as Crate
	crate.position = Vector2(x, y)
	world.add_child(crate)
	return crate


func test_a_floating_crate_carries_its_lift_and_is_dry_once_out() -> void:
	assert_true(water is WaterVolume, "the addon's tests above ran on the game's water")
	var crate: Crate = _game_crate(300.0, SURFACE_Y - 60.0)
	assert_lt(crate.density, water.density, "a crate that floats")
	for frame: int in 250:
		await get_tree().physics_frame
	# At rest on the surface the lift carries the whole weight.
	assert_almost_eq(crate.buoyancy, 1.0, 0.1, "lift as a fraction of the weight")
	assert_almost_eq(crate.buoyancy, water.buoyancy_of(crate), 0.05, "the water's own figure")
	crate.freeze = true
	crate.global_position = Vector2(300.0, SURFACE_Y - 200.0)
	for frame: int in 5:
		await get_tree().physics_frame
	assert_eq(crate.buoyancy, 0.0, "out of the water: dry")


func test_a_frozen_crate_in_the_water_gets_no_lift() -> void:
	var crate: Crate = _game_crate(500.0, SURFACE_Y + 100.0)
	crate.freeze = true
	for frame: int in 10:
		await get_tree().physics_frame
	assert_true(water.overlaps_body(crate), "the water sees the crate")
	assert_gt(water.buoyancy_of(crate), 0.0, "submerged")
	assert_eq(crate.buoyancy, 0.0, "but frozen: nothing pushes it, nothing is shown")
	assert_almost_eq(crate.global_position.y, SURFACE_Y + 100.0, 0.01)
