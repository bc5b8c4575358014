class_name PongPlayerPanel
extends PanelContainer
## One player's corner of the Pong HUD: who plays, health (bar and number), mines left
## and the next one's kind, paddle or gun and the spin paddle, and the mine effect on
## them with its time left.

const EFFECT_NAMES: Dictionary[String, String] = {
	"slow": "SLOW PADDLE", "heavy": "HEAVY PADDLE", "remote": "REMOTE CONTROL"
}

var _name: Label = Label.new()
var _health_bar: ProgressBar = ProgressBar.new()
var _health: Label = Label.new()
var _mines: Label = Label.new()
var _mode: Label = Label.new()
var _effect: Label = Label.new()


func _init() -> void:
	theme_type_variation = &"HudPanel"
	mouse_filter = MOUSE_FILTER_IGNORE
	custom_minimum_size = Vector2(300, 0)
	var column: VBoxContainer = VBoxContainer.new()
	column.add_theme_constant_override(&"separation", 3)
	add_child(column)
	_name.theme_type_variation = &"HudValue"
	column.add_child(_name)
	var row: HBoxContainer = HBoxContainer.new()
	row.add_theme_constant_override(&"separation", 8)
	column.add_child(row)
	_health_bar.show_percentage = false
	_health_bar.custom_minimum_size = Vector2(200, 14)
	_health_bar.size_flags_vertical = Control.SIZE_SHRINK_CENTER
	_health_bar.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	row.add_child(_health_bar)
	_health.theme_type_variation = &"HudValue"
	_health.custom_minimum_size = Vector2(44, 0)
	_health.horizontal_alignment = HORIZONTAL_ALIGNMENT_RIGHT
	row.add_child(_health)
	for label: Label in [_mines, _mode]:
		label.theme_type_variation = &"HudCaption"
		column.add_child(label)
	_effect.theme_type_variation = &"HudLabel"
	_effect.add_theme_color_override(&"font_color", Color(1.0, 0.75, 0.3))
	column.add_child(_effect)


## Who plays (e.g. "You · device", "Computer") in [param color].
func set_player(title: String, color: Color, max_health: int) -> void:
	_name.text = title
	_name.add_theme_color_override(&"font_color", color.lightened(0.25))
	_health_bar.max_value = max_health
	var fill: StyleBoxFlat = StyleBoxFlat.new()
	fill.bg_color = color
	_health_bar.add_theme_stylebox_override(&"fill", fill)


func show_health(health: int) -> void:
	_health_bar.value = health
	_health.text = str(health)


func show_mines(left: int, next_kind: String) -> void:
	var next: String = "  ·  next: %s" % PongMines.kind_name(next_kind) if left > 0 else ""
	_mines.text = "mines %d%s" % [left, next]


func show_modes(spin: bool, gun: bool) -> void:
	_mode.text = "%s  ·  spin %s" % ["GUN" if gun else "paddle", "ON" if spin else "off"]


## [param kind] "" for none.
func show_effect(kind: String, remaining_s: float) -> void:
	_effect.text = (
		""
		if kind.is_empty()
		else "%s  %.1f s" % [EFFECT_NAMES.get(kind, kind.to_upper()), remaining_s]
	)


func get_health_text() -> String:
	return _health.text


func get_effect_text() -> String:
	return _effect.text


func get_mode_text() -> String:
	return _mode.text


func get_mines_text() -> String:
	return _mines.text
