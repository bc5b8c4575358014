class_name UiFocus
extends RefCounted
## Focus helpers for keyboard and gamepad navigation.


## Gives [param control] the focus at the end of the frame, if it is still in the tree
## then (screens may be swapped away within the same frame).
static func grab_later(control: Control) -> void:
	_grab_if_present.call_deferred(control)


static func _grab_if_present(control: Control) -> void:
	if is_instance_valid(control) and control.is_inside_tree() and control.is_visible_in_tree():
		control.grab_focus()
