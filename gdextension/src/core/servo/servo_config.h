#pragma once

// The servo's own settings, whatever renders (servo_settings.schema.toml defines them: how the
// device's position becomes the input vector, the impacts' default material, the safety
// stage, the plane hold, telemetry), and which renderer runs. Each renderer's settings are its
// own (its Config, system/render_config.h joins them). Validated whole
// (system/settings_validation.h) and handed to the servo thread through a lock-free snapshot,
// so they may change while rendering; rejected settings leave the previous ones in force.

#include "core/render/frame.h"
#include "core/servo/servo_settings.gen.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

// InputConfig, SafetyConfig, PlaneHoldConfig, TelemetryConfig and ServoSettings:
// servo_settings.schema.toml (each field's range, unit and why it has its default).

// The servo's settings and which renderer runs: its index in the list the pipeline was
// given (the system's renderer table, whose RenderMode names the values). Switching starts it
// from rest.
struct ServoConfig : ServoSettings {
	int32_t render_mode = 0;
};

static_assert(std::is_trivially_copyable_v<ServoConfig>);

} // namespace haptics
