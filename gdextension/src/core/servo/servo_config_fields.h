#pragma once

// The servo's rows of the configuration table (core/config/config_field.h), on ServoConfig:
// sections "safety", "plane_hold" and "telemetry", and the input vector's and the impacts'
// keys of "force_model" (the movement renderer has the rest of that section).

#include "core/config/config_field.h"

#include <span>

namespace haptics {

std::span<const ConfigField> servo_config_fields();

} // namespace haptics
