extends RefCounted
## How the addon's nodes find their door: the [code]Haptics[/code] autoload, or an error that
## says how to add it.

const Haptics := preload("res://addons/haptics/door/haptics.gd")


## The [code]Haptics[/code] autoload in [param node]'s tree; null, after an error naming
## [param who] and the two ways to add it, when there is none.
static func autoload_for(node: Node, who: String) -> Haptics:
	var door: Haptics = node.get_node_or_null(^"/root/Haptics") as Haptics
	if door == null:
		push_error(
			(
				(
					"%s: no Haptics autoload; enable the Haptics plugin (Project Settings ▸ Plugins) "
					+ "or add it under [autoload] in project.godot (addon README)."
				)
				% who
			)
		)
	return door
