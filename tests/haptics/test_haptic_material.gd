extends TestSuite
## HapticMaterial as a game saves it: what a frame's contact and an impact carry, and a
## material saved before 0.3.0 (its friction named "damping") reported, not silently reset;
## and as a level declares it, on a body or on one of its shapes.

var _path: String = ""


func before_each() -> void:
	_path = "user://test_haptic_material_%d.tres" % Time.get_ticks_usec()


func after_each() -> void:
	DirAccess.remove_absolute(ProjectSettings.globalize_path(_path))


func test_a_material_gives_the_contact_and_impact_it_describes() -> void:
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = 2.5
	material.friction = 0.75
	material.impact_gain = 0.4
	var contact: HapticContactMaterial = material.contact_material()
	assert_eq(contact.stiffness_n, 2.5)
	assert_eq(contact.friction_n, 0.75)
	assert_eq(material.impact_material().gain_n_s_per_m, 0.4)


func test_a_material_saved_with_damping_says_so_when_it_loads() -> void:
	var script_path: String = "res://addons/haptics/materials/haptic_material.gd"
	var old: String = (
		'[gd_resource type="Resource" script_class="HapticMaterial" load_steps=2 format=3]\n\n'
		+ '[ext_resource type="Script" path="%s" id="1"]\n\n[resource]\nscript = ExtResource("1")\n'
		+ "stiffness = 3.0\ndamping = 0.5\n"
	)
	var file: FileAccess = FileAccess.open(_path, FileAccess.WRITE)
	file.store_string(old % script_path)
	file.close()
	expect_error("'damping' was renamed 'friction' in 0.3.0")
	var loaded: HapticMaterial = ResourceLoader.load(_path, "", ResourceLoader.CACHE_MODE_IGNORE)
	assert_not_null(loaded)
	assert_eq(loaded.stiffness, 3.0, "the rest of it loads")
	assert_eq(loaded.friction, HapticMaterial.new().friction, "damping is not read")


func test_a_shape_of_a_body_declares_its_own_material() -> void:
	# An imported level's ground: one body, a road and a verge, only the verge declared.
	var gravel: HapticMaterial = HapticMaterial.new()
	gravel.grip = 0.6
	var ground: StaticBody3D = StaticBody3D.new()
	for shape_name: String in ["Road", "Verge"]:
		var shape: CollisionShape3D = CollisionShape3D.new()
		shape.name = shape_name
		shape.shape = BoxShape3D.new()
		ground.add_child(shape)
	ground.get_node("Verge").set_meta(&"haptic_material", gravel)
	add_child_autofree(ground)
	assert_null(HapticMaterial.of_shape(ground, 0), "the road declares nothing")
	assert_eq(HapticMaterial.of_shape(ground, 1), gravel, "the verge its own")
	assert_null(HapticMaterial.of_shape(ground, 2), "no third shape")
	assert_null(HapticMaterial.of_shape(ground, -1), "no shape known")
	assert_null(HapticMaterial.of_shape(null, 0))
	var area: Area2D = Area2D.new()
	var polygon: CollisionPolygon2D = CollisionPolygon2D.new()
	polygon.polygon = PackedVector2Array([Vector2.ZERO, Vector2(8, 0), Vector2(0, 8)])
	polygon.set_meta(&"haptic_material", gravel)
	area.add_child(polygon)
	add_child_autofree(area)
	assert_eq(HapticMaterial.of_shape(area, 0), gravel, "in 2D too")
