class_name HapticsConstraint
extends HapticsRendererFace
## The constraint renderer for a game (position control against a maze's walls, as the maze
## study's constraint condition uses it): the workspace maps onto the whole maze, a finite
## proxy is held by the walls, and the hand is pulled to the proxy, k (proxy - device). Give it
## the walls and the mapping with [method set_walls], make it the active renderer with
## [method activate], feed frames as usual (an empty frame is the watchdog's heartbeat), and
## draw the avatar at [method get_proxy]'s [code]proxy[/code].

## The renderer's name in the servo.
const NAME := &"constraint"
# The door's script by its path (this script may parse before the autoload is registered).
const Haptics := preload("res://addons/haptics/door/haptics.gd")


## The constraint renderer of [param haptics] (the [code]Haptics[/code] autoload, or a door of
## a test's own).
static func of(haptics: Haptics) -> HapticsConstraint:
	return HapticsConstraint.new(haptics.renderer(NAME))


## The maze's walls as point pairs (a0, b0, a1, b1, ...) in maze units, and how the
## workspace maps onto the maze. Refused walls are reported and the previous ones stay.
func set_walls(points: PackedVector2Array, mapping: HapticMazeMapping) -> bool:
	var walls: HapticMazeWalls = HapticMazeWalls.new()
	walls.points = points
	walls.mapping = mapping
	return _renderer.send(walls)


## The proxy after the servo's latest tick (a proxy at the origin without the library).
func get_proxy() -> HapticProxyState:
	var state: HapticProxyState = HapticProxyState.decode(
		_renderer.read(HapticProxyState.SCHEMA_ID)
	)
	return state if state != null else HapticProxyState.new()


## Its settings now: the wall stiffness, the proxy's size and update (the defaults
## without the library).
func get_settings() -> HapticConstraintSettings:
	var settings: HapticConstraintSettings = HapticConstraintSettings.decode(
		_renderer.settings_bytes()
	)
	return settings if settings != null else HapticConstraintSettings.new()


## Hands it [param settings] whole (read them, change a copy, hand it back); refused ones are
## reported by field and change nothing.
func apply_settings(settings: HapticConstraintSettings) -> bool:
	return _renderer.apply_settings(settings)
