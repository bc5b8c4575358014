class_name PongMineView
extends Node3D
## A mine on the floor, coloured by its kind and pulsing; [method explode] turns it into
## an expanding flash that frees itself.

const COLORS: Dictionary[String, Color] = {
	"slow": Color(0.3, 0.7, 1.0),
	"heavy": Color(0.95, 0.55, 0.15),
	"remote": Color(0.8, 0.35, 1.0),
	"none": Color(0.9, 0.9, 0.9),
}
const EXPLOSION_S: float = 0.7

## The mine shown.
var mine: PongMines.Mine = null

var _material: StandardMaterial3D = StandardMaterial3D.new()
var _age: float = 0.0
var _exploding: bool = false
var _disc: MeshInstance3D = MeshInstance3D.new()


func setup(p_mine: PongMines.Mine) -> void:
	mine = p_mine
	position = mine.position
	var disc: CylinderMesh = CylinderMesh.new()
	disc.top_radius = PongMines.TRIGGER_RADIUS_M - PongCourt.AVATAR_BODY_RADIUS_M
	disc.bottom_radius = disc.top_radius
	disc.height = 0.03
	_material.albedo_color = COLORS.get(mine.kind, Color.WHITE)
	_material.emission_enabled = true
	_material.emission = _material.albedo_color
	_material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	disc.material = _material
	_disc.mesh = disc
	_disc.position.y = 0.015
	add_child(_disc)


## Turns the mine into a flash.
func explode() -> void:
	_exploding = true
	_age = 0.0
	_material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED


func is_exploding() -> bool:
	return _exploding


func _process(delta: float) -> void:
	_age += delta
	if not _exploding:
		_material.emission_energy_multiplier = 0.6 + 0.5 * sin(_age * 6.0)
		return
	var done: float = _age / EXPLOSION_S
	_disc.scale = Vector3(1.0 + done * 9.0, 1.0 + done * 40.0, 1.0 + done * 9.0)
	_disc.position.y = 0.015 + done * 0.6
	_material.emission_energy_multiplier = 3.0 * (1.0 - done)
	var color: Color = COLORS.get(mine.kind, Color.WHITE)
	_material.albedo_color = color.lerp(Color.WHITE, 0.5 - done * 0.5)
	_material.albedo_color.a = clampf(1.0 - done, 0.0, 1.0) * 0.8
	if done >= 1.0:
		queue_free()
