#pragma once

// The checks every value the game hands over goes through, so a message always names the
// parameter as the game spells it ("frame.contacts[3].normal: not finite (nan, 1, 0)").
// Non-finite values give INVALID_ARGUMENT, finite values outside a range OUT_OF_RANGE.

#include "core/base/status.h"
#include "core/base/vec3.h"

namespace haptics {

// p_value in [p_min, p_max].
Status check_range(const char *p_name, double p_value, double p_min, double p_max);
// Finite, at most p_max_length long and, with p_nonzero, long enough to carry a direction.
Status check_vector(const char *p_name, const Vec3 &p_value, bool p_nonzero, double p_max_length);

} // namespace haptics
