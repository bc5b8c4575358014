#include "core/servo/telemetry.h"

namespace haptics {

namespace {

void put(TelemetrySample &r_sample, size_t p_column, const Vec3 &p_value) {
	r_sample.values[p_column + 0] = static_cast<float>(p_value.x);
	r_sample.values[p_column + 1] = static_cast<float>(p_value.y);
	r_sample.values[p_column + 2] = static_cast<float>(p_value.z);
}

constexpr uint32_t SERVO_FLAGS[] = {
	TELEMETRY_FLAG_CONTACT,
	TELEMETRY_FLAG_IN_WATER,
	TELEMETRY_FLAG_WATCHDOG,
	TELEMETRY_FLAG_CLAMPED,
	TELEMETRY_FLAG_RAMPING,
	TELEMETRY_FLAG_NON_FINITE,
	TELEMETRY_FLAG_NEW_FRAME,
};

} // namespace

std::span<const uint32_t> servo_telemetry_flags() {
	return SERVO_FLAGS;
}

TelemetrySample make_telemetry_sample(double p_time_s, const Vec3 &p_input, const Vec3 &p_position,
		const ForceComponents &p_forces, uint32_t p_flags) {
	TelemetrySample sample;
	sample.values[TELEMETRY_TIME] = static_cast<float>(p_time_s);
	put(sample, TELEMETRY_INPUT, p_input);
	put(sample, TELEMETRY_POSITION, p_position);
	for (size_t part = 0; part < MAX_FORCE_PARTS; ++part) {
		put(sample, telemetry_part_column(part), p_forces.parts[part]);
	}
	put(sample, TELEMETRY_SMOOTHED, p_forces.smoothed);
	put(sample, TELEMETRY_IMPACT, p_forces.impact);
	put(sample, TELEMETRY_TOTAL, p_forces.total);
	sample.values[TELEMETRY_FLAGS] = static_cast<float>(p_flags);
	return sample;
}

} // namespace haptics
