extends TestSuite
## The HUD a player meets: compact by default (one small panel that hides little of the
## level), the lab view one key (H) away, and in the lab view no two panels on top of each
## other at the window sizes players use.

const HUD_SCENE: PackedScene = preload("res://game/ui/hud.tscn")
const SIZES: Array[Vector2] = [Vector2(1024, 600), Vector2(1280, 720), Vector2(1920, 1080)]

var _hud: Hud = null


func before_each() -> void:
	_hud = HUD_SCENE.instantiate() as Hud
	_hud.live = false
	add_child_autofree(_hud)


func _visible_panels() -> Array[Control]:
	var panels: Array[Control] = []
	for panel: Control in _hud.get_node("Root").get_children():
		if panel is Container and panel.is_visible_in_tree():
			panels.append(panel)
	return panels


# The HUD laid out in a root of [param size] (a SubViewport stands in for the window).
func _lay_out(size: Vector2) -> void:
	var root: Control = _hud.get_node("Root")
	root.set_anchors_preset(Control.PRESET_TOP_LEFT)
	root.size = size
	await wait_process_frames(3)


func test_the_compact_view_is_the_default_and_covers_little() -> void:
	for size: Vector2 in SIZES:
		await _lay_out(size)
		var covered: float = 0.0
		for panel: Control in _visible_panels():
			covered += panel.get_global_rect().get_area()
		assert_eq(_visible_panels().size(), 1, "one panel at %s" % size)
		assert_lt(covered / (size.x * size.y), 0.05, "under 5 %% of the screen at %s" % size)


func test_h_switches_to_the_lab_view_and_back() -> void:
	var switched: Array[Hud.View] = []
	_hud.view_changed.connect(func(view: Hud.View) -> void: switched.append(view))
	var key: InputEventKey = InputEventKey.new()
	key.physical_keycode = KEY_H
	key.pressed = true
	Input.parse_input_event(key)
	Input.flush_buffered_events()
	key.pressed = false
	Input.parse_input_event(key)
	Input.flush_buffered_events()
	await wait_process_frames(2)
	assert_eq(_hud.view, Hud.View.LAB)
	assert_eq(_visible_panels().size(), 3, "forces, run, plot and device")
	key.pressed = true
	Input.parse_input_event(key)
	Input.flush_buffered_events()
	await wait_process_frames(2)
	assert_eq(_hud.view, Hud.View.COMPACT)
	assert_eq(switched, [Hud.View.LAB, Hud.View.COMPACT] as Array[Hud.View])


func test_no_lab_panels_overlap_at_the_players_window_sizes() -> void:
	_hud.view = Hud.View.LAB
	for size: Vector2 in SIZES:
		await _lay_out(size)
		var panels: Array[Control] = _visible_panels()
		for i: int in panels.size():
			var rect: Rect2 = panels[i].get_global_rect()
			assert_true(
				Rect2(Vector2.ZERO, size).encloses(rect),
				"%s on screen at %s" % [panels[i].name, size]
			)
			for j: int in range(i + 1, panels.size()):
				assert_false(
					rect.intersects(panels[j].get_global_rect()),
					"%s and %s overlap at %s" % [panels[i].name, panels[j].name, size]
				)
