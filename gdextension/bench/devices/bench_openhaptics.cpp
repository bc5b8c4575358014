// OpenHaptics through the fake libHD (loaded by the backend's real dlopen path):
//  - tick: the servo side of one tick through HdDevice (read_state + write_force: two
//    seqlock copies), measured back to back while HD's fake scheduler runs at 1 kHz;
//  - encode: one run of our scheduler callback at 1 kHz as the fake times it (frame, gets of
//    position/velocity/transform/buttons, set of the force, error check, unit conversion,
//    quaternion, publish), with the fake's call recording off;
//  - max updates/s: the fake scheduler running ticks back to back.
// The real limit is HD's servo loop: 1 kHz (hdSetSchedulerRate), over the Touch's USB or
// FireWire link, which OpenHaptics owns.

#include "device_bench.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "devices/openhaptics_fake.h"

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace haptics::bench {

namespace {

using Clock = std::chrono::steady_clock;

DeviceBenchResult bench_openhaptics(double p_seconds) {
	DeviceBenchResult result;
	result.note = "HD scheduler servo loop: 1 kHz (hdSetSchedulerRate), HD owns the USB/FireWire link";
	result.bytes_per_update = 3 * sizeof(double); // HD_CURRENT_FORCE: three doubles, N.

	test::FakeHd &fake = test::fresh_fake_hd();
	fake.set_recording(0);
	auto device = openhaptics::make_device_on_runtime(test::fake_hd_path());
	if (!device->open()) {
		result.note = "could not open the fake OpenHaptics device";
		return result;
	}
	fake.wait_ticks(5, 2000);

	// Servo side, per tick.
	std::vector<double> tick_us;
	tick_us.reserve(1 << 20);
	DeviceState state;
	const auto tick_end = Clock::now() + std::chrono::duration<double>(p_seconds * 0.5);
	for (uint64_t k = 0; Clock::now() < tick_end && tick_us.size() < tick_us.capacity(); ++k) {
		const double phase = static_cast<double>(k % 1000) * 0.001 * 2.0 * M_PI;
		const ForceCommand command{ { 0.3 * std::cos(phase), 0.3 * std::sin(phase), 0.0 }, {} };
		const auto start = Clock::now();
		device->read_state(state);
		device->write_force(command);
		tick_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
	}
	result.tick_p50_us = percentile(tick_us, 50.0);
	result.tick_p99_us = percentile(tick_us, 99.0);

	// Our callback at HD's 1 kHz, as timed by the fake scheduler.
	std::vector<double> callback_ns(1 << 16);
	callback_ns.resize(fake.callback_costs(callback_ns.data(), callback_ns.size()));
	for (double &value : callback_ns) {
		value *= 1e-3;
	}
	result.encode_p50_us = percentile(callback_ns, 50.0);
	result.encode_p99_us = percentile(callback_ns, 99.0);

	// Back to back: how many callbacks one core runs per second (fake HD included).
	// Counted as forces set, so a callback that stopped would show as 0, not as fast ticks.
	fake.set_free_running(1);
	const unsigned long long sets_before = fake.force_sets();
	const unsigned long long ticks_before = fake.ticks();
	const auto free_start = Clock::now();
	std::this_thread::sleep_for(std::chrono::duration<double>(p_seconds * 0.5));
	const double elapsed_s = std::chrono::duration<double>(Clock::now() - free_start).count();
	const unsigned long long sets = fake.force_sets() - sets_before;
	const unsigned long long ticks = fake.ticks() - ticks_before;
	fake.set_free_running(0);
	result.max_update_rate_hz = static_cast<double>(sets) / elapsed_s;
	if (sets + 2 < ticks || device->status().io != DeviceIo::OK) {
		result.note = "the callback stopped during the run: " + std::string(device->status().reason);
	}

	device->close();
	fake.reset();
	return result;
}

} // namespace

HAPTICS_DEVICE_BENCH("openhaptics", bench_openhaptics);

} // namespace haptics::bench
