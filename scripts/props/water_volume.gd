class_name WaterVolume
extends Area2D
## A body of water: the haptic probe feels drag against the player's velocity and a
## constant downward inertia force while inside; rigid bodies get buoyancy from
## [member density].

## Drag coefficient c in F = −c·v, newtons per metre per second of player velocity.
@export_range(0.0, 100.0, 0.01, "suffix:N·s/m") var drag_coefficient: float = 0.6
## Constant force along "down" while inside, newtons (negative: felt as lift).
@export_range(-100.0, 100.0, 0.01, "suffix:N") var inertia_force: float = 0.4
## Water density relative to the props' densities: a crate with lower density floats.
@export_range(0.0, 10.0, 0.01) var density: float = 1.0
