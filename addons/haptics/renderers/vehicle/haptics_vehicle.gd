class_name HapticsVehicle
extends HapticsRendererFace
## The vehicle renderer for a game: a car's steering felt on a wheel (or a stick's or a
## stylus's x axis). Each physics tick the game sends its steered wheels as a
## [HapticVehicleFrame] (load, slip angle, speed, surface: [HapticVehicle3D] measures them
## from a [VehicleBody3D]); the servo turns them at 1 kHz into the tyres' aligning torque at the
## rim (a brush tyre model plus the mechanical trail), the road's texture and a steering damper,
## its forces [code]HapticForces.parts[HapticVehicleFacts.VehicleForce.ALIGNING][/code] and so
## on. The project's docs/vehicle.md has the model.

## The renderer's name in the servo.
const NAME := &"vehicle"
# The door's script by its path (this script may parse before the autoload is registered).
const Haptics := preload("res://addons/haptics/door/haptics.gd")


## The vehicle renderer of [param haptics] (the [code]Haptics[/code] autoload, or a door of a
## test's own).
static func of(haptics: Haptics) -> HapticsVehicle:
	return HapticsVehicle.new(haptics.renderer(NAME))


## Hands the servo this physics tick's steered wheels (in the vehicle mode also the watchdog's
## heartbeat); a frame it refuses is reported, naming the field, and the previous one stays.
func send_frame(frame: HapticVehicleFrame) -> bool:
	return _renderer.send(frame)


## What the servo made of the latest frame at its latest tick: the torque, the slide, the
## rim force (an empty state without the library).
func get_state() -> HapticVehicleState:
	var state: HapticVehicleState = HapticVehicleState.decode(
		_renderer.read(HapticVehicleState.SCHEMA_ID)
	)
	return state if state != null else HapticVehicleState.new()


## Its settings now: the tyres, the strength, the damper (the defaults without the library).
func get_settings() -> HapticVehicleSettings:
	var settings: HapticVehicleSettings = HapticVehicleSettings.decode(_renderer.settings_bytes())
	return settings if settings != null else HapticVehicleSettings.new()


## Hands it [param settings] whole (read them, change a copy, hand it back); refused ones are
## reported by field and change nothing.
func apply_settings(settings: HapticVehicleSettings) -> bool:
	return _renderer.apply_settings(settings)
