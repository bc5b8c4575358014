#pragma once

// Whether a RenderConfig may be handed to the servo: the servo's settings and every
// renderer's within their schemas' limits (servo_settings.schema.toml, each renderer's
// schema), then the limits that join fields (each renderer's validate(), e.g. Pong's
// beginner plane inside its court), and a render mode the table has.

#include "core/base/status.h"
#include "system/render_config.h"

namespace haptics {

Status validate_render_config(const RenderConfig &p_config);

} // namespace haptics
