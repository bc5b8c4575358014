extends RefCounted
## What a person sees go wrong in a laid-out screen, found from its Controls: a control off
## the screen, two controls drawn over each other, text cut off by its control, or text
## smaller than [constant MIN_FONT_PX].

## The smallest text a person reads comfortably on a laptop screen.
const MIN_FONT_PX: int = 12
## Overlaps and overhangs smaller than this many pixels are anti-aliasing, not layout.
const SLACK_PX: float = 1.0


## Every problem of the visible Controls under [param root], which is laid out in a screen of
## [param screen] pixels. Controls with the meta [code]layout_overlay[/code] are meant to sit
## over others (a gauge on a level, a marker on a plot) and only checked for being on screen.
static func problems(root: Node, screen: Vector2) -> PackedStringArray:
	var found: PackedStringArray = []
	var leaves: Array[Control] = []
	_collect(root, leaves)
	var bounds: Rect2 = Rect2(Vector2.ZERO, screen).grow(SLACK_PX)
	for control: Control in leaves:
		var rect: Rect2 = control.get_global_rect()
		if not bounds.encloses(rect):
			found.append("%s off the screen: %s" % [_name(control), rect])
		var font_px: int = control.get_theme_font_size(&"font_size")
		if _shows_text(control) and font_px < MIN_FONT_PX:
			found.append("%s: text at %d px" % [_name(control), font_px])
		if _text_cut(control):
			found.append(
				(
					"%s: text cut off (needs %s, has %s)"
					% [_name(control), control.get_combined_minimum_size(), control.size]
				)
			)
	for i: int in leaves.size():
		if leaves[i].has_meta(&"layout_overlay"):
			continue
		for j: int in range(i + 1, leaves.size()):
			if leaves[j].has_meta(&"layout_overlay"):
				continue
			var overlap: Rect2 = leaves[i].get_global_rect().intersection(
				leaves[j].get_global_rect()
			)
			if overlap.size.x > SLACK_PX and overlap.size.y > SLACK_PX:
				found.append(
					"%s and %s overlap by %s" % [_name(leaves[i]), _name(leaves[j]), overlap.size]
				)
	return found


# The visible Controls a person reads or presses: text, buttons, fields, bars, pictures;
# containers and panels hold them and are not compared themselves.
static func _collect(node: Node, r_leaves: Array[Control]) -> void:
	if node is CanvasItem and not (node as CanvasItem).is_visible_in_tree():
		return
	if node is Control and _is_leaf(node as Control):
		r_leaves.append(node as Control)
		return
	for child: Node in node.get_children():
		_collect(child, r_leaves)


static func _is_leaf(control: Control) -> bool:
	if control is Container or control is Panel or control is ColorRect or control is ScrollBar:
		return false
	if control is Label and (control as Label).text.strip_edges().is_empty():
		return false
	return (
		control.get_child_count(false) == 0
		or control is BaseButton
		or control is Range
		or control is LineEdit
		or control is Label
	)


static func _shows_text(control: Control) -> bool:
	return control is Label or control is Button or control is LineEdit or control is TextEdit


static func _text_cut(control: Control) -> bool:
	if control is Label:
		var label: Label = control as Label
		if label.clip_text or label.text_overrun_behavior != TextServer.OVERRUN_NO_TRIMMING:
			return label.get_minimum_size().x > label.size.x + SLACK_PX
		if label.autowrap_mode != TextServer.AUTOWRAP_OFF:
			return label.get_visible_line_count() < label.get_line_count()
		return label.get_minimum_size().x > label.size.x + SLACK_PX
	if control is Button:
		return control.get_combined_minimum_size().x > control.size.x + SLACK_PX
	return false


static func _name(control: Control) -> String:
	var text: String = ""
	if control is Label:
		text = (control as Label).text
	elif control is Button:
		text = (control as Button).text
	return "%s%s" % [control.name, (" '%s'" % text.left(30)) if not text.is_empty() else ""]
