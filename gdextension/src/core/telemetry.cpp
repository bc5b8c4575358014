#include "core/telemetry.h"

namespace haptics {

namespace {

void put(TelemetrySample &r_sample, size_t p_column, const Vec3 &p_value) {
	r_sample.values[p_column + 0] = static_cast<float>(p_value.x);
	r_sample.values[p_column + 1] = static_cast<float>(p_value.y);
	r_sample.values[p_column + 2] = static_cast<float>(p_value.z);
}

} // namespace

TelemetrySample make_telemetry_sample(double p_time_s, const Vec3 &p_input, const Vec3 &p_position,
		const ForceComponents &p_forces, uint32_t p_flags) {
	TelemetrySample sample;
	sample.values[TELEMETRY_TIME] = static_cast<float>(p_time_s);
	put(sample, TELEMETRY_INPUT, p_input);
	put(sample, TELEMETRY_POSITION, p_position);
	put(sample, TELEMETRY_NORMAL, p_forces.normal);
	put(sample, TELEMETRY_FRICTION, p_forces.friction);
	put(sample, TELEMETRY_WEIGHT, p_forces.weight);
	put(sample, TELEMETRY_DRAG, p_forces.drag);
	put(sample, TELEMETRY_INERTIA, p_forces.inertia);
	put(sample, TELEMETRY_SMOOTHED, p_forces.smoothed);
	put(sample, TELEMETRY_IMPACT, p_forces.impact);
	put(sample, TELEMETRY_TOTAL, p_forces.total);
	sample.values[TELEMETRY_FLAGS] = static_cast<float>(p_flags);
	return sample;
}

} // namespace haptics
