// The evdev backend against the scripted kernel: the servo-side tick through EvdevDevice
// (a seqlock copy each way; the I/O thread runs meanwhile at 500 Hz), one protocol update
// (newtons -> (direction, level) -> the 48-byte ff_effect), and how many EVIOCSFF updates
// per second the protocol layer sustains on one core when the "kernel" answers at once.

#include "dev_tools/evdev/scripted_evdev_device.h"
#include "device_bench.h"
#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_effect.h"

#include <chrono>
#include <cmath>
#include <memory>

namespace {

using namespace haptics;
using namespace haptics::evdev;
using Clock = std::chrono::steady_clock;

double micros(Clock::duration p_duration) {
	return std::chrono::duration<double, std::micro>(p_duration).count();
}

// A force that changes every call (so every update is a real upload), circling at 3 N.
Vec3 circling_force(uint64_t p_step) {
	const double angle = static_cast<double>(p_step) * 0.01;
	return Vec3(3.0 * std::cos(angle), 3.0 * std::sin(angle), 0.0);
}

bench::DeviceBenchResult bench_evdev(double p_seconds) {
	bench::DeviceBenchResult result;
	const auto kernel = std::make_shared<ScriptedEvdevKernel>();
	kernel->set_recording(false); // Counters only: a record would allocate per call.
	const double phase_s = p_seconds / 3.0;

	{ // The servo's tick through the device.
		auto device = make_scripted_device(kernel);
		if (!device->open()) {
			result.note = "could not open the scripted device";
			return result;
		}
		std::vector<double> samples;
		samples.reserve(200000);
		DeviceState state;
		const auto end = Clock::now() + std::chrono::duration<double>(phase_s);
		for (uint64_t step = 0; Clock::now() < end && samples.size() < samples.capacity(); ++step) {
			const auto t0 = Clock::now();
			device->read_state(state);
			device->write_force({ circling_force(step), {} });
			samples.push_back(micros(Clock::now() - t0));
		}
		device->close();
		result.tick_p50_us = bench::percentile(samples, 50.0);
		result.tick_p99_us = bench::percentile(samples, 99.0);
	}

	{ // One protocol update's encoding, timed in batches (one is ~the clock's resolution).
		constexpr int BATCH = 64;
		std::vector<double> samples;
		samples.reserve(20000);
		FfForceMapping mapping;
		FfEffectBytes bytes;
		FfConstantEffect effect;
		effect.id = 0;
		uint64_t step = 0;
		volatile uint8_t sink = 0; // Keeps the encoding from being optimised away.
		const auto end = Clock::now() + std::chrono::duration<double>(phase_s);
		while (Clock::now() < end && samples.size() < samples.capacity()) {
			const auto t0 = Clock::now();
			for (int i = 0; i < BATCH; ++i) {
				const FfConstantForce force = map_force_to_constant(circling_force(step++), mapping);
				effect.direction = force.direction;
				effect.level = force.level;
				encode_constant_effect(effect, bytes);
				sink = static_cast<uint8_t>(bytes[4] ^ bytes[16]);
			}
			samples.push_back(micros(Clock::now() - t0) / BATCH);
		}
		(void)sink;
		result.encode_p50_us = bench::percentile(samples, 50.0);
		result.encode_p99_us = bench::percentile(samples, 99.0);
	}

	{ // Updates per second: map + EVIOCSFF into the scripted kernel (its mutex included).
		const int fd = kernel->open_device(kernel->script().path.c_str());
		EvdevFfFeatures features;
		EvdevConstantForce channel;
		if (fd < 0 || !query_ff_features(*kernel, fd, kernel->script().path.c_str(), features) ||
				!channel.start(*kernel, fd, features, kernel->script().path.c_str())) {
			result.note = "could not start the effect on the scripted kernel";
			return result;
		}
		FfForceMapping mapping;
		const uint64_t uploads_before = channel.uploads();
		const auto t0 = Clock::now();
		const auto end = t0 + std::chrono::duration<double>(phase_s);
		uint64_t step = 0;
		while (Clock::now() < end) {
			for (int i = 0; i < 256; ++i) {
				channel.update(map_force_to_constant(circling_force(step++), mapping));
			}
		}
		const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
		result.max_update_rate_hz = static_cast<double>(channel.uploads() - uploads_before) / elapsed;
		channel.stop_and_erase();
		kernel->close(fd);
	}

	result.bytes_per_update = static_cast<double>(FF_EFFECT_SIZE); // One EVIOCSFF; no re-play.
	result.note = "1 EVIOCSFF/update; hid-pidff -> 1-2 HID reports, 1/ms on full-speed USB: I/O at 500 Hz";
	return result;
}

} // namespace

HAPTICS_DEVICE_BENCH("evdev", bench_evdev);
