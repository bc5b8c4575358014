class_name StatusLine
extends RefCounted
## A scene's one line of status at the top left, on the HUD's dark panel: legible over any
## sky or floor the camera shows (white text straight on the pale sky was barely legible).

const THEME := preload("res://assets/ui/theme.tres")


## A new status [Label] in a [CanvasLayer] under [param parent], [param font_size] px.
static func add_to(parent: Node, font_size: int) -> Label:
	var layer: CanvasLayer = CanvasLayer.new()
	var panel: PanelContainer = PanelContainer.new()
	panel.theme = THEME
	panel.theme_type_variation = &"HudPanel"
	panel.position = Vector2(12.0, 8.0)
	var label: Label = Label.new()
	label.add_theme_font_size_override(&"font_size", font_size)
	panel.add_child(label)
	layer.add_child(panel)
	parent.add_child(layer)
	return label
