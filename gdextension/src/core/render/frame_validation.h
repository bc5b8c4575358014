#pragma once

// Validation of what the game sends every physics tick: a rejected frame or impact never
// reaches the servo, and the caller keeps its last good one. Messages name the parameter as
// the game spells it, e.g. "frame.contacts[3].normal: not finite (nan, 1, 0)" (value_checks.h).

#include "core/base/status.h"
#include "core/render/frame.h"

namespace haptics {

Status validate_frame(const Frame &p_frame);
Status validate_impact(const ImpactEvent &p_event);
Status validate_contact_material(const char *p_name, const ContactMaterial &p_material);
Status validate_impact_material(const char *p_name, const ImpactMaterial &p_material);

} // namespace haptics
