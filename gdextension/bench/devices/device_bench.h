#pragma once

// The device backends' benchmark (haptics_device_bench): per backend, the servo-side cost of
// one tick including the protocol encoding, and the highest update rate its protocol layer
// sustains against a scripted transport that answers at once (the bus is the limit on real
// hardware; this measures our side). Each backend registers one function in its own
// bench_<backend>.cpp with HAPTICS_DEVICE_BENCH. Numbers, not tests.

#include <string>
#include <vector>

namespace haptics::bench {

struct DeviceBenchResult {
	std::string backend; // e.g. "hid-pid", "evdev", "falcon", "openhaptics", "dualsense"
	double tick_p50_us = 0.0; // Servo tick through the device (encode + exchange), per tick.
	double tick_p99_us = 0.0;
	double encode_p50_us = 0.0; // One protocol update (force -> bytes), per update.
	double encode_p99_us = 0.0;
	double max_update_rate_hz = 0.0; // Protocol updates per second on one core.
	double bytes_per_update = 0.0; // On the wire, for a changing force.
	std::string note; // What limits the real device, e.g. "USB full speed: 1 report/ms".
};

using DeviceBenchFunction = DeviceBenchResult (*)(double p_seconds);

struct DeviceBenchRegistrar {
	DeviceBenchRegistrar(const char *p_name, DeviceBenchFunction p_function);
};

struct DeviceBenchEntry {
	const char *name;
	DeviceBenchFunction function;
};

std::vector<DeviceBenchEntry> &device_benches();

// Percentile (0..100) of p_values (copied and sorted).
double percentile(std::vector<double> p_values, double p_percent);

} // namespace haptics::bench

#define HAPTICS_DEVICE_BENCH_CONCAT2(a, b) a##b
#define HAPTICS_DEVICE_BENCH_CONCAT(a, b) HAPTICS_DEVICE_BENCH_CONCAT2(a, b)
#define HAPTICS_DEVICE_BENCH(p_name, p_function) \
	static const ::haptics::bench::DeviceBenchRegistrar HAPTICS_DEVICE_BENCH_CONCAT(device_bench_, __LINE__)(p_name, p_function)
