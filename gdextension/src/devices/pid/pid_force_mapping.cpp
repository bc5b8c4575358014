#include "devices/pid/pid_force_mapping.h"

#include <cmath>
#include <numbers>

namespace haptics::pid {

namespace {

constexpr double TURN = 65536.0; // Linux direction units per 360°.

uint16_t direction_from_radians(double p_theta) {
	const double units = std::fmod(std::round(p_theta / (2.0 * std::numbers::pi) * TURN) + 2.0 * TURN, TURN);
	return static_cast<uint16_t>(static_cast<uint32_t>(units) & 0xFFFFu);
}

int16_t level_from_ratio(double p_ratio) {
	const double clamped = p_ratio < -1.0 ? -1.0 : (p_ratio > 1.0 ? 1.0 : p_ratio);
	return static_cast<int16_t>(std::lround(clamped * 0x7FFF));
}

} // namespace

PidForce map_force(const Vec3 &p_force_n, const PidForceMapping &p_mapping, uint16_t p_previous_direction) {
	PidForce result;
	result.direction = p_previous_direction;
	const double scale = p_mapping.max_force_n > 0.0 ? 1.0 / p_mapping.max_force_n : 0.0;
	const double hid_x = p_force_n.x * scale * (p_mapping.invert_x ? -1.0 : 1.0);
	const double hid_y = -p_force_n.y * scale * (p_mapping.invert_y ? -1.0 : 1.0);
	if (!std::isfinite(hid_x) || !std::isfinite(hid_y)) {
		return result; // Zero level.
	}
	if (p_mapping.wheel) {
		result.direction = PID_DIRECTION_PLUS_X;
		result.level = level_from_ratio(hid_x);
		return result;
	}
	const double magnitude = std::hypot(hid_x, hid_y);
	result.level = level_from_ratio(magnitude);
	if (result.level == 0) {
		return result;
	}
	const double theta = std::atan2(hid_x, -hid_y);
	const double previous = static_cast<double>(p_previous_direction) / TURN * 2.0 * std::numbers::pi;
	const double delta = std::remainder(theta - previous, 2.0 * std::numbers::pi);
	if (std::fabs(delta) > 0.5 * std::numbers::pi) {
		result.direction = direction_from_radians(theta + std::numbers::pi);
		result.level = static_cast<int16_t>(-result.level);
	} else {
		result.direction = direction_from_radians(theta);
	}
	return result;
}

Vec3 force_from_pid(const PidForce &p_force, const PidForceMapping &p_mapping) {
	const double theta = static_cast<double>(p_force.direction) / TURN * 2.0 * std::numbers::pi;
	const double level = static_cast<double>(p_force.level) / 0x7FFF * p_mapping.max_force_n;
	const double hid_x = level * std::sin(theta) * (p_mapping.invert_x ? -1.0 : 1.0);
	const double hid_y = -level * std::cos(theta) * (p_mapping.invert_y ? -1.0 : 1.0);
	if (p_mapping.wheel) {
		return Vec3{ hid_x, 0.0, 0.0 };
	}
	return Vec3{ hid_x, -hid_y, 0.0 };
}

} // namespace haptics::pid
