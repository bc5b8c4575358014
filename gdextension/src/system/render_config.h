#pragma once

// Everything the game configures, as one value: the servo's own settings and each
// renderer's, under the renderer's name (renderer_table.h). HapticsSystem::configure()
// validates it whole (settings_validation.h) and hands each part to the servo on its own channel. To
// change one field:
//   RenderConfig config = system.config();  config.pong.gravity_m_per_s2 = 4.0;
//   system.configure(config);

#include "core/servo/servo_config.h"
#include "system/renderer_table.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace haptics {

struct RenderConfig {
	ServoConfig servo;
#define HAPTICS_SETTINGS_OF(MODE, name, Class) Class::Config name;
	HAPTICS_RENDERERS(HAPTICS_SETTINGS_OF)
#undef HAPTICS_SETTINGS_OF
};

static_assert(std::is_trivially_copyable_v<RenderConfig>);

// The values of ServoConfig::render_mode: RenderMode::PONG is the Pong renderer's.
struct RenderMode {
#define HAPTICS_MODE_OF(MODE, name, Class) MODE,
	enum : int32_t { HAPTICS_RENDERERS(HAPTICS_MODE_OF) };
#undef HAPTICS_MODE_OF
};

// Calls p_visit with r_config's settings of the renderer with p_mode (its Config); false, and
// no call, for a mode the table has not.
template <typename Config, typename F>
bool visit_renderer_settings(Config &r_config, int64_t p_mode, F &&p_visit) {
	int64_t mode = 0;
	bool found = false;
#define HAPTICS_VISIT_OF(MODE, name, Class) \
	if (mode++ == p_mode) { \
		found = true; \
		p_visit(r_config.name); \
	}
	HAPTICS_RENDERERS(HAPTICS_VISIT_OF)
#undef HAPTICS_VISIT_OF
	return found;
}

#define HAPTICS_COUNT_ONE(MODE, name, Class) +1
inline constexpr size_t RENDER_MODE_COUNT = 0 HAPTICS_RENDERERS(HAPTICS_COUNT_ONE);
#undef HAPTICS_COUNT_ONE

} // namespace haptics
