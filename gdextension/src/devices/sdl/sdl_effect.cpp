#include "devices/sdl/sdl_effect.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics::sdl {

namespace {

double finite_or_zero(double p_value) {
	return std::isfinite(p_value) ? p_value : 0.0;
}

int16_t level_of(double p_fraction) {
	const double clamped = std::clamp(p_fraction, -1.0, 1.0);
	return static_cast<int16_t>(std::lround(clamped * SDL_LEVEL_MAX));
}

uint16_t magnitude_of(double p_fraction) {
	return static_cast<uint16_t>(std::lround(std::clamp(p_fraction, 0.0, 1.0) * SDL_LEVEL_MAX));
}

} // namespace

SdlConstantForce map_force_to_sdl(const Vec3 &p_force_n, const SdlForceMapping &p_mapping) {
	SdlConstantForce force;
	const double full = p_mapping.max_force_n > 0.0 && std::isfinite(p_mapping.max_force_n) ? p_mapping.max_force_n : 1.0;
	const double x = finite_or_zero(p_force_n.x) * (p_mapping.invert_x ? -1.0 : 1.0);
	const double y = finite_or_zero(p_force_n.y) * (p_mapping.invert_y ? -1.0 : 1.0);
	if (p_mapping.steering) {
		force.direction_type = SDL_HAPTIC_STEERING_AXIS;
		force.level = level_of(x / full);
		return force;
	}
	force.direction_type = SDL_HAPTIC_POLAR;
	force.level = level_of(std::hypot(x, y) / full);
	if (force.level == 0) {
		return force;
	}
	// Clockwise from north (+y): atan2(x, y).
	const double degrees = std::atan2(x, y) * 180.0 / std::numbers::pi;
	force.direction = static_cast<int32_t>(std::lround(degrees * 100.0));
	force.direction = ((force.direction % 36000) + 36000) % 36000;
	return force;
}

SDL_HapticEffect constant_effect(const SdlConstantForce &p_force) {
	SDL_HapticEffect effect{};
	effect.type = SDL_HAPTIC_CONSTANT;
	effect.constant.type = SDL_HAPTIC_CONSTANT;
	effect.constant.direction.type = p_force.direction_type;
	effect.constant.direction.dir[0] = p_force.direction;
	effect.constant.length = SDL_EFFECT_LENGTH_MS;
	effect.constant.level = p_force.level;
	return effect;
}

Vec3 constant_effect_force_n(const SDL_HapticEffect &p_effect, double p_max_force_n) {
	if (p_effect.type != SDL_HAPTIC_CONSTANT) {
		return {};
	}
	const double magnitude = p_effect.constant.level / static_cast<double>(SDL_LEVEL_MAX) * p_max_force_n;
	if (p_effect.constant.direction.type == SDL_HAPTIC_STEERING_AXIS) {
		return Vec3{ magnitude, 0.0, 0.0 };
	}
	const double radians = p_effect.constant.direction.dir[0] / 100.0 * std::numbers::pi / 180.0;
	return Vec3{ magnitude * std::sin(radians), magnitude * std::cos(radians), 0.0 };
}

SdlRumbleLevels SdlRumbleEnvelope::update(double p_peak_n, double p_dt_s, const SdlRumbleMapping &p_mapping) {
	const double peak = std::fabs(finite_or_zero(p_peak_n));
	const double input = p_mapping.impact_full_scale_n > 0.0 ? std::min(peak / p_mapping.impact_full_scale_n, 1.0) : 0.0;
	const double kept = p_mapping.release_s > 0.0 ? level_ * std::exp(-std::max(p_dt_s, 0.0) / p_mapping.release_s) : 0.0;
	level_ = std::max(input, kept);
	if (level_ < p_mapping.floor) {
		level_ = 0.0;
	}
	const double knee = p_mapping.large_motor_knee;
	SdlRumbleLevels levels;
	levels.small = magnitude_of(level_);
	levels.large = knee < 1.0 ? magnitude_of((level_ - knee) / (1.0 - knee)) : 0;
	return levels;
}

SDL_HapticEffect leftright_effect(const SdlRumbleLevels &p_levels) {
	SDL_HapticEffect effect{};
	effect.type = SDL_HAPTIC_LEFTRIGHT;
	effect.leftright.type = SDL_HAPTIC_LEFTRIGHT;
	effect.leftright.length = SDL_EFFECT_LENGTH_MS;
	effect.leftright.large_magnitude = p_levels.large;
	effect.leftright.small_magnitude = p_levels.small;
	return effect;
}

} // namespace haptics::sdl
