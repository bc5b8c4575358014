class_name UiFocus
extends RefCounted
## Focus helpers for keyboard and gamepad navigation.


## Gives [param control] the focus at the end of the frame, if it is still in the tree
## then (screens may be swapped away within the same frame).
static func grab_later(control: Control) -> void:
	# By instance ID: a deferred call cannot even be made with a Control freed in the meantime
	# (the engine fails converting the argument before the function could check it).
	_grab_if_present.call_deferred(control.get_instance_id())


static func _grab_if_present(control_id: int) -> void:
	var control: Control = instance_from_id(control_id) as Control
	if control != null and control.is_inside_tree() and control.is_visible_in_tree():
		control.grab_focus()
