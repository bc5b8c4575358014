#include "devices/dualsense/dualsense_triggers.h"

#include <cstring>

namespace haptics::dualsense {

namespace {

// Zone mask in p0..p1 and 3-bit values in p2..p5, both little-endian (DSC;
// docs/devices/dualsense.md, "Adaptive-trigger blocks").
void pack_zones(uint8_t p_mode, const uint8_t (&p_values)[TRIGGER_ZONES], TriggerEffect &r_effect) {
	uint32_t mask = 0;
	uint32_t values = 0;
	for (int zone = 0; zone < TRIGGER_ZONES; ++zone) {
		if (p_values[zone] == 0) {
			continue;
		}
		mask |= 1u << zone;
		values |= static_cast<uint32_t>(p_values[zone] - 1u) << (3 * zone);
	}
	r_effect = trigger_off();
	r_effect.bytes[0] = p_mode;
	r_effect.bytes[1] = static_cast<uint8_t>(mask);
	r_effect.bytes[2] = static_cast<uint8_t>(mask >> 8);
	for (int b = 0; b < 4; ++b) {
		r_effect.bytes[3 + b] = static_cast<uint8_t>(values >> (8 * b));
	}
}

Status check_int(const char *p_name, int p_value, int p_min, int p_max) {
	if (p_value < p_min || p_value > p_max) {
		return Status::error(StatusCode::OUT_OF_RANGE, "dualsense trigger %s must be in [%d, %d] (got %d)", p_name, p_min,
				p_max, p_value);
	}
	return Status::success();
}

Status check_zones(const char *p_name, const uint8_t (&p_values)[TRIGGER_ZONES]) {
	bool any = false;
	for (int zone = 0; zone < TRIGGER_ZONES; ++zone) {
		if (p_values[zone] > TRIGGER_MAX_STRENGTH) {
			return Status::error(StatusCode::OUT_OF_RANGE, "dualsense trigger %s[%d] must be in [0, %d] (got %d)", p_name, zone,
					TRIGGER_MAX_STRENGTH, p_values[zone]);
		}
		any = any || p_values[zone] != 0;
	}
	if (!any) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "dualsense trigger %s: no active zone (use trigger_off)", p_name);
	}
	return Status::success();
}

void fill_from(int p_start_zone, int p_value, uint8_t (&r_values)[TRIGGER_ZONES]) {
	for (int zone = 0; zone < TRIGGER_ZONES; ++zone) {
		r_values[zone] = zone >= p_start_zone ? static_cast<uint8_t>(p_value) : 0;
	}
}

} // namespace

bool TriggerEffect::operator==(const TriggerEffect &p_other) const {
	return std::memcmp(bytes, p_other.bytes, sizeof(bytes)) == 0;
}

TriggerEffect trigger_off() {
	return TriggerEffect{}; // Mode 0x05, parameters zero.
}

Status trigger_feedback_zones(const uint8_t (&p_strengths)[TRIGGER_ZONES], TriggerEffect &r_effect) {
	const Status valid = check_zones("strengths", p_strengths);
	if (!valid) {
		return valid;
	}
	pack_zones(TRIGGER_MODE_FEEDBACK, p_strengths, r_effect);
	return Status::success();
}

Status trigger_feedback(int p_start_zone, int p_strength, TriggerEffect &r_effect) {
	Status valid = check_int("start_zone", p_start_zone, 0, TRIGGER_ZONES - 1);
	if (valid) {
		valid = check_int("strength", p_strength, 1, TRIGGER_MAX_STRENGTH);
	}
	if (!valid) {
		return valid;
	}
	uint8_t strengths[TRIGGER_ZONES];
	fill_from(p_start_zone, p_strength, strengths);
	pack_zones(TRIGGER_MODE_FEEDBACK, strengths, r_effect);
	return Status::success();
}

Status trigger_vibration_zones(const uint8_t (&p_amplitudes)[TRIGGER_ZONES], int p_frequency_hz, TriggerEffect &r_effect) {
	Status valid = check_zones("amplitudes", p_amplitudes);
	if (valid) {
		valid = check_int("frequency_hz", p_frequency_hz, 1, 255);
	}
	if (!valid) {
		return valid;
	}
	pack_zones(TRIGGER_MODE_VIBRATION, p_amplitudes, r_effect);
	r_effect.bytes[1 + TRIGGER_VIBRATION_FREQUENCY_PARAM] = static_cast<uint8_t>(p_frequency_hz);
	return Status::success();
}

Status trigger_vibration(int p_start_zone, int p_amplitude, int p_frequency_hz, TriggerEffect &r_effect) {
	Status valid = check_int("start_zone", p_start_zone, 0, TRIGGER_ZONES - 1);
	if (valid) {
		valid = check_int("amplitude", p_amplitude, 1, TRIGGER_MAX_STRENGTH);
	}
	if (!valid) {
		return valid;
	}
	uint8_t amplitudes[TRIGGER_ZONES];
	fill_from(p_start_zone, p_amplitude, amplitudes);
	return trigger_vibration_zones(amplitudes, p_frequency_hz, r_effect);
}

Status trigger_weapon(int p_start_zone, int p_end_zone, int p_strength, TriggerEffect &r_effect) {
	Status valid = check_int("start_zone", p_start_zone, 2, 7);
	if (valid) {
		valid = check_int("end_zone", p_end_zone, p_start_zone + 1, 8);
	}
	if (valid) {
		valid = check_int("strength", p_strength, 1, TRIGGER_MAX_STRENGTH);
	}
	if (!valid) {
		return valid;
	}
	const uint32_t zones = (1u << p_start_zone) + (1u << p_end_zone);
	r_effect = trigger_off();
	r_effect.bytes[0] = TRIGGER_MODE_WEAPON;
	r_effect.bytes[1] = static_cast<uint8_t>(zones);
	r_effect.bytes[2] = static_cast<uint8_t>(zones >> 8);
	r_effect.bytes[3] = static_cast<uint8_t>(p_strength - 1);
	return Status::success();
}

bool unpack_trigger_zones(const TriggerEffect &p_effect, uint8_t (&r_values)[TRIGGER_ZONES]) {
	std::memset(r_values, 0, sizeof(r_values));
	if (p_effect.mode() != TRIGGER_MODE_FEEDBACK && p_effect.mode() != TRIGGER_MODE_VIBRATION) {
		return false;
	}
	const uint32_t mask = static_cast<uint32_t>(p_effect.param(0)) | static_cast<uint32_t>(p_effect.param(1)) << 8;
	uint32_t values = 0;
	for (size_t b = 0; b < 4; ++b) {
		values |= static_cast<uint32_t>(p_effect.param(2 + b)) << (8 * b);
	}
	for (int zone = 0; zone < TRIGGER_ZONES; ++zone) {
		if (mask & (1u << zone)) {
			r_values[zone] = static_cast<uint8_t>(((values >> (3 * zone)) & 0x7u) + 1u);
		}
	}
	return true;
}

int trigger_feedback_strength(const TriggerEffect &p_effect) {
	if (p_effect.mode() != TRIGGER_MODE_FEEDBACK) {
		return 0;
	}
	uint8_t strengths[TRIGGER_ZONES];
	unpack_trigger_zones(p_effect, strengths);
	int strongest = 0;
	for (const uint8_t strength : strengths) {
		strongest = strength > strongest ? strength : strongest;
	}
	return strongest;
}

} // namespace haptics::dualsense
