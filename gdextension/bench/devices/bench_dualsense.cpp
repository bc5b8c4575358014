// haptics_device_bench entry for the DualSense (device_bench.h): against the scripted pad,
//  - tick: what the servo pays per tick through the device (read_state + write_force: two
//    seqlock copies and the impact peak's atomic max), with the I/O thread running;
//  - encode: one output report, planner decision + common block + framing, Bluetooth (the
//    costlier: 78 bytes and the CRC-32); USB printed beside it;
//  - max updates/s: whole I/O cycles on one core with a force that changes every cycle
//    (plan, encode, write to the pad, drain and decode its input report, publish).

#include "device_bench.h"

#include "dev_tools/dualsense/scripted_dualsense_device.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_io.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace haptics::bench {

namespace {

using Clock = std::chrono::steady_clock;
using namespace haptics::dualsense;

double us_since(Clock::time_point p_start) {
	return std::chrono::duration<double, std::micro>(Clock::now() - p_start).count();
}

// A force and impact that change every call, as during a rumble decay.
ForceCommand command_at(int p_index) {
	ForceCommand command;
	const double phase = 0.01 * p_index;
	command.force_n = Vec3{ 0.0, 1.0 + std::sin(phase), 0.0 };
	command.impact_n = Vec3{ 0.0, 3.0 * std::sin(7.0 * phase), 0.0 };
	return command;
}

std::vector<double> time_encodes(Bus p_bus, double p_seconds, volatile uint8_t &r_sink) {
	auto pad = std::make_shared<ScriptedDualSense>(ScriptedDualSenseOptions{ p_bus });
	auto transport = make_scripted_transport(pad);
	DualSenseIo io(transport.get(), MappingConfig{}, 0.05);
	io.begin(p_bus, RumbleRecipe::IMPROVED);
	OutputPlanner planner;
	std::vector<double> samples;
	OutputReport report;
	const auto end = Clock::now() + std::chrono::duration<double>(p_seconds);
	for (int i = 0; Clock::now() < end; ++i) {
		const ForceCommand command = command_at(i);
		const auto start = Clock::now();
		OutputState state;
		const uint32_t fields = planner.plan(command, std::fabs(command.impact_n.y), 0.004, state);
		io.encode(state, fields | FIELD_RUMBLE, report);
		samples.push_back(us_since(start));
		r_sink = static_cast<uint8_t>(r_sink + report.bytes[report.size - 1]);
	}
	return samples;
}

DeviceBenchResult bench_dualsense(double p_seconds) {
	DeviceBenchResult result;
	volatile uint8_t sink = 0;

	// Encode: BT and USB.
	const std::vector<double> bt = time_encodes(Bus::BLUETOOTH, 0.25 * p_seconds, sink);
	const std::vector<double> usb = time_encodes(Bus::USB, 0.15 * p_seconds, sink);
	result.encode_p50_us = percentile(bt, 50.0);
	result.encode_p99_us = percentile(bt, 99.0);

	// Whole I/O cycles, a report every cycle (BT: the costlier framing).
	{
		auto pad = std::make_shared<ScriptedDualSense>(ScriptedDualSenseOptions{ Bus::BLUETOOTH });
		auto transport = make_scripted_transport(pad);
		transport->open();
		DualSenseIo io(transport.get(), MappingConfig{}, 0.05);
		io.begin(Bus::BLUETOOTH, RumbleRecipe::IMPROVED);
		DeviceExchange exchange;
		exchange.reset();
		uint64_t cycles = 0;
		const auto start = Clock::now();
		const auto end = start + std::chrono::duration<double>(0.3 * p_seconds);
		while (Clock::now() < end) {
			const ForceCommand command = command_at(static_cast<int>(cycles));
			exchange.write_command(command);
			io.offer_impact(command.impact_n);
			io.io_cycle(exchange, 0.004);
			++cycles;
		}
		const double seconds = us_since(start) * 1e-6;
		const ScriptedPadCounters counters = pad->counters();
		result.max_update_rate_hz = static_cast<double>(counters.reports_accepted) / seconds;
		result.bytes_per_update =
				counters.reports_accepted > 0 ? static_cast<double>(counters.bytes_accepted) / static_cast<double>(counters.reports_accepted) : 0.0;
		std::printf("dualsense: %llu I/O cycles, %llu BT reports accepted, %llu rejected\n",
				static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(counters.reports_accepted),
				static_cast<unsigned long long>(counters.reports_rejected));
	}

	// Servo side through the open device (its I/O thread runs at 250 Hz meanwhile).
	{
		ScriptedDualSenseSetup setup = make_scripted_device(Bus::USB);
		if (setup.device->open()) {
			std::vector<double> samples;
			DeviceState state;
			const auto end = Clock::now() + std::chrono::duration<double>(0.3 * p_seconds);
			for (int i = 0; Clock::now() < end; ++i) {
				const ForceCommand command = command_at(i);
				const auto start = Clock::now();
				setup.device->read_state(state);
				setup.device->write_force(command);
				samples.push_back(us_since(start));
			}
			setup.device->close();
			result.tick_p50_us = percentile(samples, 50.0);
			result.tick_p99_us = percentile(samples, 99.0);
		}
	}

	std::printf("dualsense: encode p50/p99 BT %.3f/%.3f us (78 B + CRC), USB %.3f/%.3f us (63 B)\n", result.encode_p50_us,
			result.encode_p99_us, percentile(usb, 50.0), percentile(usb, 99.0));
	result.note = "pad: ~250 Hz USB / 125 Hz BT I/O, reports only on change (+2/s keep-alive); USB FS 1 report/ms max";
	return result;
}

} // namespace

HAPTICS_DEVICE_BENCH("dualsense", bench_dualsense);

} // namespace haptics::bench
