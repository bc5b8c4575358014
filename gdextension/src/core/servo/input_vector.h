#pragma once

// The input vector i every renderer receives (RenderInput::input): the device's position as
// a dimensionless push, |i| <= 1, as the movement-based method reads the stylus.

#include "core/base/vec3.h"

namespace haptics {

// Device position (m) -> input vector. Divides by p_radius_m, clamps to the unit ball, then
// applies the dead zone: |i| <= dz gives 0, otherwise |i| is remapped (|i| - dz) / (1 - dz)
// keeping the direction, so the output is continuous at the dead-zone edge and still
// reaches 1 at the workspace edge. p_radius_m > 0, p_dead_zone in [0, 1).
Vec3 input_vector(const Vec3 &p_position_m, double p_radius_m, double p_dead_zone);

} // namespace haptics
