#pragma once

// The renderers the system is assembled from: ONE row each, in render-mode order (a mode's
// value is its row's index, its name's index in HapticsSystem.get_renderer_names(); the first
// is the default).
//   X(MODE, name, Class)
// MODE names the RenderMode constant, `name` the renderer (its RenderConfig member and the
// name GDScript's Haptics.renderer() takes), Class the renderer (core/render/renderer.h says
// what it offers the system; Class::Port, when it has one, what it takes and gives GDScript).
// A new renderer is its folder under src/renderers/<name>/ (with <name>_renderer.h, which
// the build includes here) and one row: its settings, its validation, its port and the
// names of its force components follow from the row.

#include "renderer_headers.gen.h"

#define HAPTICS_RENDERERS(X) \
	X(MOVEMENT, movement, MovementRenderer) \
	X(CONSTRAINT, constraint, ConstraintRenderer) \
	X(PONG, pong, PongRenderer) \
	X(VEHICLE, vehicle, VehicleRenderer)
