extends SceneTree
## Screenshot helper for level 1 (not a test suite: the runner only loads test_*.gd).
##
## Run under a display (Xvfb works), e.g.
## [codeblock]
## DISPLAY=:95 tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     --fixed-fps 50 -s res://tests/world/capture_level.gd -- ARGS
## [/codeblock]
## ARGS: player positions [code]x,y x,y …[/code] (one PNG each), [code]run:F1,F2,…[/code]
## (frames of an autopilot run), [code]overview[/code] (the whole level in two halves),
## [code]drop[/code] (a crate falling on the sub) or [code]bump[/code] (the sub hitting a
## ceiling). PNGs go to /tmp/shots/.


func _initialize() -> void:
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var level: Level = (load("res://game/levels/level_1.tscn") as PackedScene).instantiate()
	root.add_child(level)
	var player: Player = level.get_node(^"Player")
	player.use_keyboard = false
	(player.get_node(^"HapticProbe") as HapticProbe).drive_input = false
	DirAccess.make_dir_recursive_absolute("/tmp/shots")
	await process_frame
	await process_frame
	if args.size() > 0 and args[0] == "overview":
		(player.get_node(^"Camera2D") as Camera2D).enabled = false
		var cam: Camera2D = Camera2D.new()
		cam.zoom = Vector2(1280.0 / 4480.0, 1280.0 / 4480.0)
		level.add_child(cam)
		cam.make_current()
		for half: int in 2:
			cam.position = Vector2(2240.0 + half * 4480.0, 720.0)
			for f: int in 5:
				await process_frame
			var img: Image = root.get_viewport().get_texture().get_image()
			img.save_png("/tmp/shots/overview_%d.png" % half)
		quit()
		return
	if args.size() > 0 and args[0] == "drop":
		player.global_position = Vector2(3100.0, 620.0)
		player.reset_physics_interpolation()
		var crate: Node2D = (load("res://game/props/crate.tscn") as PackedScene).instantiate()
		crate.position = Vector2(3100.0, 470.0)
		level.add_child(crate)
		player.get_node(^"Camera2D").call(&"reset_smoothing")
		for frame: int in 40:
			await physics_frame
			if frame >= 20 and frame % 3 == 0:
				await process_frame
				var img: Image = root.get_viewport().get_texture().get_image()
				img.save_png("/tmp/shots/drop_%d.png" % frame)
		quit()
		return
	if args.size() > 0 and args[0] == "bump":
		player.global_position = Vector2(3000.0, 600.0)
		player.reset_physics_interpolation()
		player.get_node(^"Camera2D").call(&"reset_smoothing")
		for frame: int in 60:
			await physics_frame
			player.input_vector = Vector2(0.3, -1.0) if frame < 40 else Vector2.ZERO
			if frame >= 30 and frame % 2 == 0 and frame < 46:
				await process_frame
				var img: Image = root.get_viewport().get_texture().get_image()
				img.save_png("/tmp/shots/bump_%d.png" % frame)
		quit()
		return
	if args.size() > 0 and args[0].begins_with("run:"):
		var frames: PackedStringArray = args[0].substr(4).split(",")
		var pilot: Autopilot = Autopilot.new(level.get_autopilot_path())
		var frame: int = 0
		for target: String in frames:
			while frame < target.to_int():
				await physics_frame
				pilot.drive(player, 1.0 / 50.0)
				frame += 1
			await process_frame
			root.get_viewport().get_texture().get_image().save_png("/tmp/shots/run_%d.png" % frame)
			print("saved frame ", frame, " at ", player.global_position)
		quit()
		return
	for i: int in args.size():
		var xy: PackedStringArray = args[i].split(",")
		player.global_position = Vector2(xy[0].to_float(), xy[1].to_float())
		player.reset_physics_interpolation()
		var cam: Camera2D = player.get_node(^"Camera2D")
		for f: int in 3:
			await process_frame
		cam.reset_smoothing()
		for f: int in 20:
			await process_frame
		root.get_viewport().get_texture().get_image().save_png("/tmp/shots/shot_%d.png" % i)
		print("saved ", i, " at ", player.global_position)
	quit()
