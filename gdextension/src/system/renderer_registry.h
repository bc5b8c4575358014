#pragma once

// The renderer table (renderer_table.h) as data, for what walks it at run time: the binding
// (the renderers' names, which GDScript chooses a renderer by) and the tests.

#include "core/render/renderer_info.h"

#include <span>

namespace haptics {

struct RegisteredRenderer {
	const char *name; // "movement"
	const RendererInfo *info;
};

// In render-mode order: a row's index is its mode's value.
std::span<const RegisteredRenderer> registered_renderers();

} // namespace haptics
