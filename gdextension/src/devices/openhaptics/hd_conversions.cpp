#include "devices/openhaptics/hd_conversions.h"

#include <algorithm>
#include <cmath>

namespace haptics::openhaptics {

namespace {

Vec3 clamp_length(const Vec3 &p_v, double p_max) {
	const double magnitude = length(p_v);
	return magnitude > p_max ? p_v * (p_max / magnitude) : p_v;
}

} // namespace

Status workspace_from_hd_box(const double p_box_mm[6], HdWorkspace &r_workspace) {
	static constexpr char AXES[] = { 'x', 'y', 'z' };
	double centre[3];
	double half[3];
	for (int axis = 0; axis < 3; ++axis) {
		const double low = p_box_mm[axis];
		const double high = p_box_mm[axis + 3];
		if (!std::isfinite(low) || !std::isfinite(high) || !(low < high)) {
			return Status::error(StatusCode::DEVICE_ERROR,
					"HD_USABLE_WORKSPACE_DIMENSIONS: %c from %g to %g mm is not a range (min, min, min, max, max, max)",
					AXES[axis], low, high);
		}
		centre[axis] = 0.5 * (low + high) * MM_TO_M;
		half[axis] = 0.5 * (high - low) * MM_TO_M;
	}
	r_workspace.centre_m = Vec3{ centre[0], centre[1], centre[2] };
	r_workspace.half_extent_m = Vec3{ half[0], half[1], half[2] };
	r_workspace.radius_m = std::min({ half[0], half[1], half[2] });
	return Status::success();
}

Vec3 position_from_hd(const double p_position_mm[3], const Vec3 &p_centre_m) {
	return Vec3{ p_position_mm[0], p_position_mm[1], p_position_mm[2] } * MM_TO_M - p_centre_m;
}

bool position_plausible(const Vec3 &p_position_m) {
	return is_finite(p_position_m) && length(p_position_m) <= MAX_PLAUSIBLE_POSITION_M;
}

Vec3 velocity_from_hd(const double p_velocity_mm_s[3]) {
	return Vec3{ p_velocity_mm_s[0], p_velocity_mm_s[1], p_velocity_mm_s[2] } * MM_TO_M;
}

Orientation orientation_from_hd_transform(const double p_transform[16]) {
	// r(row, column) of the rotation; column-major storage puts column c at [4c .. 4c+2].
	const auto r = [p_transform](int p_row, int p_column) { return p_transform[4 * p_column + p_row]; };
	// Not a rotation at all (non-finite, or columns far from unit length, e.g. all zero):
	// no orientation rather than a made-up one.
	for (int column = 0; column < 3; ++column) {
		const double norm = std::sqrt(r(0, column) * r(0, column) + r(1, column) * r(1, column) + r(2, column) * r(2, column));
		if (!std::isfinite(norm) || !(norm > 0.5 && norm < 1.5)) {
			return Orientation{};
		}
	}
	// Shepperd's method: branch on the largest of w, x, y, z so the square root is taken of
	// the biggest (best conditioned) diagonal combination.
	const double trace = r(0, 0) + r(1, 1) + r(2, 2);
	Orientation q;
	if (trace > 0.0) {
		const double s = 2.0 * std::sqrt(1.0 + trace);
		q.w = 0.25 * s;
		q.x = (r(2, 1) - r(1, 2)) / s;
		q.y = (r(0, 2) - r(2, 0)) / s;
		q.z = (r(1, 0) - r(0, 1)) / s;
	} else if (r(0, 0) > r(1, 1) && r(0, 0) > r(2, 2)) {
		const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + r(0, 0) - r(1, 1) - r(2, 2)));
		if (s == 0.0) {
			return Orientation{};
		}
		q.w = (r(2, 1) - r(1, 2)) / s;
		q.x = 0.25 * s;
		q.y = (r(0, 1) + r(1, 0)) / s;
		q.z = (r(0, 2) + r(2, 0)) / s;
	} else if (r(1, 1) > r(2, 2)) {
		const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + r(1, 1) - r(0, 0) - r(2, 2)));
		if (s == 0.0) {
			return Orientation{};
		}
		q.w = (r(0, 2) - r(2, 0)) / s;
		q.x = (r(0, 1) + r(1, 0)) / s;
		q.y = 0.25 * s;
		q.z = (r(1, 2) + r(2, 1)) / s;
	} else {
		const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + r(2, 2) - r(0, 0) - r(1, 1)));
		if (s == 0.0) {
			return Orientation{};
		}
		q.w = (r(1, 0) - r(0, 1)) / s;
		q.x = (r(0, 2) + r(2, 0)) / s;
		q.y = (r(1, 2) + r(2, 1)) / s;
		q.z = 0.25 * s;
	}
	// The gimbal's matrix is orthonormal only to the encoders' precision: renormalise, and
	// keep w >= 0 so the same rotation always reads the same.
	const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
	if (!(norm > 0.0) || !std::isfinite(norm)) {
		return Orientation{};
	}
	const double sign = q.w < 0.0 ? -1.0 : 1.0;
	return Orientation{ sign * q.w / norm, sign * q.x / norm, sign * q.y / norm, sign * q.z / norm };
}

Vec3 bounded_force(const ForceCommand &p_command, double p_continuous_limit_n, double p_peak_limit_n) {
	if (!is_finite(p_command.force_n) || !is_finite(p_command.impact_n) || !(p_peak_limit_n > 0.0)) {
		return Vec3{};
	}
	Vec3 continuous = p_command.force_n - p_command.impact_n;
	if (p_continuous_limit_n > 0.0) {
		continuous = clamp_length(continuous, p_continuous_limit_n);
	}
	return clamp_length(continuous + p_command.impact_n, p_peak_limit_n);
}

} // namespace haptics::openhaptics
