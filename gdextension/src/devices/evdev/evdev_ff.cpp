#include "devices/evdev/evdev_ff.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics::evdev {

void encode_constant_effect(const FfConstantEffect &p_effect, FfEffectBytes &r_bytes) {
	r_bytes.fill(0);
	uint8_t *bytes = r_bytes.data();
	put_u16(bytes, FF_EFFECT_TYPE_OFFSET, EVDEV_FF_CONSTANT);
	put_u16(bytes, FF_EFFECT_ID_OFFSET, static_cast<uint16_t>(p_effect.id));
	put_u16(bytes, FF_EFFECT_DIRECTION_OFFSET, p_effect.direction);
	put_u16(bytes, FF_EFFECT_REPLAY_LENGTH_OFFSET, p_effect.replay_length_ms);
	put_u16(bytes, FF_EFFECT_REPLAY_DELAY_OFFSET, p_effect.replay_delay_ms);
	put_u16(bytes, FF_CONSTANT_LEVEL_OFFSET, static_cast<uint16_t>(p_effect.level));
}

void encode_rumble_effect(const FfRumbleEffect &p_effect, FfEffectBytes &r_bytes) {
	r_bytes.fill(0);
	uint8_t *bytes = r_bytes.data();
	put_u16(bytes, FF_EFFECT_TYPE_OFFSET, EVDEV_FF_RUMBLE);
	put_u16(bytes, FF_EFFECT_ID_OFFSET, static_cast<uint16_t>(p_effect.id));
	put_u16(bytes, FF_EFFECT_REPLAY_LENGTH_OFFSET, p_effect.replay_length_ms);
	put_u16(bytes, FF_RUMBLE_STRONG_OFFSET, p_effect.strong_magnitude);
	put_u16(bytes, FF_RUMBLE_WEAK_OFFSET, p_effect.weak_magnitude);
}

FfEffectFields decode_ff_effect(const FfEffectBytes &p_bytes) {
	const uint8_t *bytes = p_bytes.data();
	FfEffectFields fields;
	fields.type = get_u16(bytes, FF_EFFECT_TYPE_OFFSET);
	fields.id = get_s16(bytes, FF_EFFECT_ID_OFFSET);
	fields.direction = get_u16(bytes, FF_EFFECT_DIRECTION_OFFSET);
	fields.trigger_button = get_u16(bytes, FF_EFFECT_TRIGGER_BUTTON_OFFSET);
	fields.trigger_interval = get_u16(bytes, FF_EFFECT_TRIGGER_INTERVAL_OFFSET);
	fields.replay_length_ms = get_u16(bytes, FF_EFFECT_REPLAY_LENGTH_OFFSET);
	fields.replay_delay_ms = get_u16(bytes, FF_EFFECT_REPLAY_DELAY_OFFSET);
	fields.constant_level = get_s16(bytes, FF_CONSTANT_LEVEL_OFFSET);
	fields.rumble_strong = get_u16(bytes, FF_RUMBLE_STRONG_OFFSET);
	fields.rumble_weak = get_u16(bytes, FF_RUMBLE_WEAK_OFFSET);
	fields.periodic_waveform = get_u16(bytes, FF_PERIODIC_WAVEFORM_OFFSET);
	fields.periodic_period_ms = get_u16(bytes, FF_PERIODIC_PERIOD_OFFSET);
	fields.periodic_magnitude = get_s16(bytes, FF_PERIODIC_MAGNITUDE_OFFSET);
	return fields;
}

void encode_input_event(uint16_t p_type, uint16_t p_code, int32_t p_value, InputEventBytes &r_bytes) {
	r_bytes.fill(0);
	put_u16(r_bytes.data(), INPUT_EVENT_TYPE_OFFSET, p_type);
	put_u16(r_bytes.data(), INPUT_EVENT_CODE_OFFSET, p_code);
	put_s32(r_bytes.data(), INPUT_EVENT_VALUE_OFFSET, p_value);
}

InputEvent decode_input_event(const uint8_t *p_bytes) {
	InputEvent event;
	int64_t seconds = 0;
	int64_t microseconds = 0;
	for (size_t i = 0; i < 8; ++i) {
		seconds |= static_cast<int64_t>(p_bytes[i]) << (8 * i);
		microseconds |= static_cast<int64_t>(p_bytes[8 + i]) << (8 * i);
	}
	event.time_s = seconds;
	event.time_us = microseconds;
	event.type = get_u16(p_bytes, INPUT_EVENT_TYPE_OFFSET);
	event.code = get_u16(p_bytes, INPUT_EVENT_CODE_OFFSET);
	event.value = get_s32(p_bytes, INPUT_EVENT_VALUE_OFFSET);
	return event;
}

namespace {

double finite_or_zero(double p_value) {
	return std::isfinite(p_value) ? p_value : 0.0;
}

int16_t level_of(double p_fraction) {
	const double clamped = std::clamp(p_fraction, -1.0, 1.0);
	return static_cast<int16_t>(std::lround(clamped * FF_LEVEL_MAX));
}

} // namespace

FfConstantForce map_force_to_constant(const Vec3 &p_force_n, const FfForceMapping &p_mapping) {
	const double max_force = p_mapping.max_force_n;
	if (!(max_force > 0.0) || !std::isfinite(max_force)) {
		return {};
	}
	const double x = finite_or_zero(p_force_n.x) * (p_mapping.invert_x ? -1.0 : 1.0);
	if (p_mapping.shape == EvdevShape::WHEEL) {
		const int16_t level = level_of(x / max_force);
		return { level == 0 ? uint16_t(0) : FF_DIRECTION_STEERING, level };
	}
	// Axis frame: +Y toward the user, i.e. device -y (see the header).
	const double axis_y = -finite_or_zero(p_force_n.y) * (p_mapping.invert_y ? -1.0 : 1.0);
	const double magnitude = std::hypot(x, axis_y);
	const int16_t level = level_of(magnitude / max_force);
	if (level == 0) {
		return {};
	}
	// X = sin(theta), Y = -cos(theta)  =>  theta = atan2(X, -Y), in [-pi, pi].
	double turns = std::atan2(x, -axis_y) / (2.0 * std::numbers::pi);
	if (turns < 0.0) {
		turns += 1.0;
	}
	const long direction = std::lround(turns * 65536.0) & 0xffff; // 1.0 turn wraps to 0.
	return { static_cast<uint16_t>(direction), level };
}

} // namespace haptics::evdev
