extends Node
## What the screenshot tours share: [code]--out=DIR[/code] (default [member out]) read at
## ready, the folder made, [method _tour] started once the tree is up, and [method _shot]:
## a PNG of the window after [param wait_seconds] and two drawn frames.

var out: String = "user://shots"


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--out="):
			out = arg.get_slice("=", 1)
		else:
			_option(arg)
	DirAccess.make_dir_recursive_absolute(out)
	_tour.call_deferred()


## A tour's own command-line option (every user argument but [code]--out[/code]).
func _option(_arg: String) -> void:
	pass


## The walk through the screens; each tour overrides it and quits when done.
func _tour() -> void:
	pass


func _shot(shot_name: String, wait_seconds: float = 0.5) -> void:
	if wait_seconds > 0.0:
		await get_tree().create_timer(wait_seconds, true).timeout
	for i: int in 2:
		await get_tree().process_frame
	await RenderingServer.frame_post_draw
	var path: String = "%s/%s.png" % [out, shot_name]
	get_viewport().get_texture().get_image().save_png(path)
	print("saved %s (%d fps)" % [path, Engine.get_frames_per_second()])
