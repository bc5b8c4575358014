// "hid-pid": the HID PID backend against the scripted AJ joystick. The servo tick only
// copies through the DeviceExchange (the I/O thread runs at 250 Hz beside it); a protocol
// update is the force mapping plus the Set Effect and Set Constant Force encodings; the
// update rate is ConstantForceEffect::update with a changing force through the scripted
// transport (firmware model included), on one core.

#include "device_bench.h"

#include "dev_tools/pid/scripted_pid_device.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/hid/report_descriptor.h"
#include "devices/pid/pid_backend.h"
#include "devices/pid/pid_effect.h"
#include "devices/pid/pid_force_mapping.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace haptics::bench {

namespace {

using Clock = std::chrono::steady_clock;

Clock::time_point after(double p_seconds) {
	return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p_seconds));
}

double elapsed_us(Clock::time_point p_begin, Clock::time_point p_end) {
	return std::chrono::duration<double, std::micro>(p_end - p_begin).count();
}

Vec3 swirling_force(uint64_t p_step) {
	const double angle = static_cast<double>(p_step) * 0.01;
	const double magnitude = 1.0 + 0.5 * std::sin(static_cast<double>(p_step) * 0.003);
	return Vec3{ magnitude * std::sin(angle), magnitude * std::cos(angle), 0.0 };
}

DeviceBenchResult bench_pid(double p_seconds) {
	DeviceBenchResult result;
	result.note = "USB full-speed interrupt OUT, bInterval 1 ms: <= 1000 reports/s (hidraw writes are synchronous); we run "
				  "250 Hz, <= 2 reports per cycle, only changed values";

	// Servo tick through the device, its I/O thread running against the scripted joystick.
	auto joystick = std::make_shared<pid::ScriptedPidJoystick>(pid::ScriptedFirmware::AJ, 0);
	std::unique_ptr<HapticDevice> device = pid::make_scripted_device(joystick);
	if (!device->open()) {
		result.note = "could not open the scripted joystick";
		return result;
	}
	std::vector<double> ticks;
	const Clock::time_point tick_end = after(p_seconds * 0.3);
	DeviceState state;
	for (uint64_t step = 0; Clock::now() < tick_end; ++step) {
		const Clock::time_point begin = Clock::now();
		(void)device->read_state(state);
		(void)device->write_force(ForceCommand{ swirling_force(step), {} });
		ticks.push_back(elapsed_us(begin, Clock::now()));
	}
	device->close();
	result.tick_p50_us = percentile(ticks, 50.0);
	result.tick_p99_us = percentile(ticks, 99.0);

	// Rig for the protocol layer: the same descriptor, an uploaded effect.
	auto firmware = std::make_shared<pid::ScriptedPidJoystick>(pid::ScriptedFirmware::AJ, 0);
	std::unique_ptr<hid::HidTransport> transport = pid::make_scripted_transport(firmware);
	std::vector<uint8_t> bytes;
	hid::ReportDescriptor descriptor;
	pid::PidLayout layout;
	pid::ConstantForceEffect effect;
	if (!transport->open() || !transport->report_descriptor(bytes) ||
			!hid::ReportDescriptor::parse(bytes, hid::ParseOptions{ false }, descriptor) ||
			!pid::PidLayout::build(std::move(descriptor), layout) || !pid::initialize_device(*transport, layout) ||
			!effect.upload(*transport, layout, 0, 0)) {
		result.note = "could not set up the scripted effect";
		return result;
	}

	// One update's encoding: force -> (direction, level) -> Set Effect + Set Constant Force.
	const pid::PidForceMapping mapping;
	std::vector<double> encodes;
	pid::PidReport set_effect;
	pid::PidReport set_constant;
	uint16_t direction = 0;
	const Clock::time_point encode_end = after(p_seconds * 0.3);
	for (uint64_t step = 0; Clock::now() < encode_end; ++step) {
		const Clock::time_point begin = Clock::now();
		const pid::PidForce force = pid::map_force(swirling_force(step * 7), mapping, direction);
		(void)pid::encode_set_effect(layout, effect.block_index(), force.direction, set_effect);
		(void)pid::encode_set_constant_force(layout, effect.block_index(), force.level, set_constant);
		encodes.push_back(elapsed_us(begin, Clock::now()));
		direction = force.direction;
	}
	result.encode_p50_us = percentile(encodes, 50.0);
	result.encode_p99_us = percentile(encodes, 99.0);

	// Sustained updates with a force that changes every time, through the transport.
	uint64_t updates = 0;
	const uint64_t bytes_before = firmware->stats().bytes_to_device;
	const Clock::time_point rate_begin = Clock::now();
	const Clock::time_point rate_end = after(p_seconds * 0.4);
	while (Clock::now() < rate_end) {
		for (int i = 0; i < 64; ++i, ++updates) {
			const pid::PidForce force = pid::map_force(swirling_force(updates * 7), mapping, direction);
			(void)effect.update(*transport, force.direction, force.level);
			direction = force.direction;
		}
	}
	const double rate_seconds = std::chrono::duration<double>(Clock::now() - rate_begin).count();
	result.max_update_rate_hz = static_cast<double>(updates) / rate_seconds;
	result.bytes_per_update = static_cast<double>(firmware->stats().bytes_to_device - bytes_before) / static_cast<double>(updates);
	(void)effect.erase(*transport);
	return result;
}

} // namespace

HAPTICS_DEVICE_BENCH("hid-pid", bench_pid);

} // namespace haptics::bench
