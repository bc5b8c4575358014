class_name HapticsMovement
extends HapticsRendererFace
## The movement-based renderer for a game (acceleration control, the default): the probe's
## frames become the paper's forces, F_n = -k p, F_f = -b r, weight, water drag and inertia,
## smoothed to 1 kHz. Its settings are the contact law ([HapticForceModelSettings]) and the
## output filter ([HapticSmoothingSettings]); its forces are
## [code]HapticForces.parts[HapticMovementFacts.MovementForce.NORMAL][/code] and so on.

## The renderer's name in the servo.
const NAME := &"movement"
# The door's script by its path (this script may parse before the autoload is registered).
const Haptics := preload("res://addons/haptics/door/haptics.gd")


## The movement renderer of [param haptics] (the [code]Haptics[/code] autoload, or a door of
## a test's own).
static func of(haptics: Haptics) -> HapticsMovement:
	return HapticsMovement.new(haptics.renderer(NAME))


## Its settings now (the defaults without the library).
func get_settings() -> HapticMovementSettings:
	var settings: HapticMovementSettings = HapticMovementSettings.decode(_renderer.settings_bytes())
	return settings if settings != null else HapticMovementSettings.new()


## Hands it [param settings] whole (read them, change a copy, hand it back); refused ones are
## reported by field and change nothing.
func apply_settings(settings: HapticMovementSettings) -> bool:
	return _renderer.apply_settings(settings)
