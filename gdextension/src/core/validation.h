#pragma once

// Validation of everything the game hands to the core. A rejected value never reaches the
// servo: the caller keeps its last good frame or configuration. Messages name the
// parameter as the game spells it, e.g. "frame.contacts[3].normal: not finite (nan, 1, 0)"
// or "smoothing.cutoff_hz must be in [0.5, 60] (got 200)": configuration fields by the key
// the game sets them with (config_fields.h).
// Non-finite values give INVALID_ARGUMENT, finite values outside a range OUT_OF_RANGE.

#include "core/config.h"
#include "core/frame.h"
#include "core/status.h"

namespace haptics {

inline constexpr double MIN_RATE_HZ = 250.0;
inline constexpr double MAX_RATE_HZ = 4000.0;
inline constexpr double DEFAULT_RATE_HZ = 1000.0;

Status validate_frame(const Frame &p_frame);
Status validate_impact(const ImpactEvent &p_event);
Status validate_contact_material(const char *p_name, const ContactMaterial &p_material);
Status validate_impact_material(const char *p_name, const ImpactMaterial &p_material);
// Every field against the field table (config_fields.h), the fields' joint limits
// (validate_pong_config), and the render mode.
Status validate_render_config(const RenderConfig &p_config);
// Servo rate in Hz, [MIN_RATE_HZ, MAX_RATE_HZ].
Status validate_rate(double p_rate_hz);
// Manual step period in s, [1 / MAX_RATE_HZ, 1 / MIN_RATE_HZ].
Status validate_step_dt(double p_dt_s);

// Building blocks, exposed for the binding's own parameters.
Status check_range(const char *p_name, double p_value, double p_min, double p_max);
Status check_vector(const char *p_name, const Vec3 &p_value, bool p_nonzero, double p_max_length);

} // namespace haptics
