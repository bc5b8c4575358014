#pragma once

// The renderers the engine is assembled from: ONE row each, in render-mode order (a mode's
// value is its row's index, RENDER_MODE_<MODE> in GDScript; the first is the default).
//   X(MODE, name, Class)
// MODE names the RenderMode constant, `name` the renderer (its RenderConfig member, what
// GDScript's render-mode names are made of), Class the renderer (core/render/renderer.h says
// what it offers the engine). A new renderer is its folder under src/renderers/ and one row
// here; everything else (its settings in RenderConfig, its rows in the configuration table,
// its channels, its RENDER_MODE_* and TELEMETRY_FLAG_* constants, the names of its force
// components in get_forces()) follows from the row.

#include "renderers/constraint/constraint_renderer.h"
#include "renderers/movement/movement_renderer.h"
#include "renderers/pong/pong_renderer.h"

#define HAPTICS_RENDERERS(X) \
	X(MOVEMENT, movement, MovementRenderer) \
	X(CONSTRAINT, constraint, ConstraintRenderer) \
	X(PONG, pong, PongRenderer)
