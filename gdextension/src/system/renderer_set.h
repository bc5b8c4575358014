#pragma once

// Every renderer of the table (renderer_table.h) with its channels, built once per HapticsSystem.
// The servo ticks the renderers (`all`, in render-mode order); the game reaches a renderer's
// channels by its name, e.g. system.renderers().pong.channels, and its port
// (system.renderers().pong.port, or all_ports[mode]) for what only that renderer offers.

#include "core/render/renderer.h"
#include "core/render/renderer_channels.h"
#include "core/render/renderer_port.h"
#include "system/render_config.h"
#include "system/renderer_table.h"

#include <array>

namespace haptics {

template <typename R>
struct RendererSlot {
	typename R::Channels channels;
	R renderer{ channels };
	typename R::Port port{ channels }; // The game's end of what only this renderer offers.
};

struct RendererSet {
#define HAPTICS_SLOT_OF(MODE, name, Class) RendererSlot<Class> name;
	HAPTICS_RENDERERS(HAPTICS_SLOT_OF)
#undef HAPTICS_SLOT_OF

#define HAPTICS_RENDERER_OF(MODE, name, Class) &name.renderer,
	const std::array<Renderer *, RENDER_MODE_COUNT> all{ HAPTICS_RENDERERS(HAPTICS_RENDERER_OF) };
#undef HAPTICS_RENDERER_OF
#define HAPTICS_CHANNELS_OF(MODE, name, Class) &name.channels,
	const std::array<RendererChannels *, RENDER_MODE_COUNT> all_channels{ HAPTICS_RENDERERS(HAPTICS_CHANNELS_OF) };
#undef HAPTICS_CHANNELS_OF
#define HAPTICS_PORT_OF(MODE, name, Class) &name.port,
	const std::array<RendererPort *, RENDER_MODE_COUNT> all_ports{ HAPTICS_RENDERERS(HAPTICS_PORT_OF) };
#undef HAPTICS_PORT_OF

	// Game thread: each renderer's settings onto its channel (the servo takes them next tick).
	void publish_settings(const RenderConfig &p_config) {
#define HAPTICS_PUBLISH_OF(MODE, name, Class) name.channels.settings.store(p_config.name);
		HAPTICS_RENDERERS(HAPTICS_PUBLISH_OF)
#undef HAPTICS_PUBLISH_OF
	}
};

} // namespace haptics
