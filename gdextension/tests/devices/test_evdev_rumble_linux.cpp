// A rumble-only gamepad on evdev (hid-playstation's DualSense node, xpad...): the device opens
// as a vibration device with one FF_RUMBLE effect, the servo's impacts become the motors'
// magnitudes as the envelope rule says, the continuous force is not felt, and closing leaves
// the motors off with the effect erased.

#include "dev_tools/evdev/scripted_evdev_device.h"
#include "devices/evdev/evdev_device.h"
#include "devices/evdev/evdev_rumble.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

using namespace haptics;
using namespace haptics::evdev;
namespace {

// struct ff_effect for FF_RUMBLE: type 0x50 @0, id @2, strong @16, weak @18 (docs/devices/evdev.md).
std::vector<uint8_t> expected_rumble_effect(int16_t p_id, uint16_t p_strong, uint16_t p_weak) {
	std::vector<uint8_t> bytes(48, 0);
	bytes[0] = 0x50;
	bytes[2] = static_cast<uint8_t>(static_cast<uint16_t>(p_id) & 0xff);
	bytes[3] = static_cast<uint8_t>(static_cast<uint16_t>(p_id) >> 8);
	bytes[16] = static_cast<uint8_t>(p_strong & 0xff);
	bytes[17] = static_cast<uint8_t>(p_strong >> 8);
	bytes[18] = static_cast<uint8_t>(p_weak & 0xff);
	bytes[19] = static_cast<uint8_t>(p_weak >> 8);
	return bytes;
}

} // namespace

TEST_CASE("evdev rumble envelope: impact peak / full scale, weak motor always, strong above the knee, release, floor") {
	const RumbleMapping mapping;
	RumbleEnvelope envelope;
	FfRumbleLevels levels = envelope.update(1.5, 0.002, mapping); // Half of the 3 N full scale.
	CHECK(levels.weak == 32768);
	CHECK(levels.strong == 0);
	levels = envelope.update(3.0, 0.002, mapping);
	CHECK(levels.weak == 0xffff);
	CHECK(levels.strong == 0xffff);
	levels = envelope.update(9.0, 0.002, mapping); // Clamped.
	CHECK(levels.weak == 0xffff);
	// No new hit: one time constant later the level is 1/e.
	levels = envelope.update(0.0, mapping.release_s, mapping);
	CHECK(envelope.level() == doctest::Approx(std::exp(-1.0)));
	CHECK(levels.weak == static_cast<uint16_t>(std::lround(std::exp(-1.0) * 0xffff)));
	CHECK(levels.strong == 0);
	levels = envelope.update(0.0, 10 * mapping.release_s, mapping); // Below the floor: silence.
	CHECK(levels == FfRumbleLevels{});
	CHECK(envelope.update(std::nan(""), 0.002, mapping) == FfRumbleLevels{});
}

TEST_CASE("evdev device: a rumble-only gamepad opens as a vibration device - impacts are rumble, contact is not") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>(scripted_gamepad_script());
	EvdevDeviceConfig config;
	config.path = scripted_gamepad_script().path;
	auto device = std::make_unique<EvdevDevice>(kernel, config);
	REQUIRE(device->open().ok());
	CHECK(device->output() == EvdevOutput::RUMBLE);
	const DeviceCapabilities capabilities = device->capabilities();
	CHECK(capabilities.output == ForceOutput::VIBRATION);
	CHECK(capabilities.output_dof == 0);
	CHECK(capabilities.input_dof == 2);

	// Start: one rumble with both motors off (id -1), play it; the player's gain left alone.
	const std::vector<ScriptedEvdevCall> start = evdev_test::ff_calls(kernel->calls());
	REQUIRE(start.size() == 2);
	CHECK(start[0].bytes == expected_rumble_effect(-1, 0, 0));
	CHECK(start[1].bytes == evdev_test::expected_event(EVDEV_EV_FF, 0, 1));

	// A contact force alone: nothing to feel.
	for (int i = 0; i < 20; ++i) {
		REQUIRE(device->write_force(ForceCommand{ Vec3(0.0, 2.0, 0.0), Vec3() }) == DeviceIo::OK);
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	CHECK(kernel->rendered().rumble_weak == 0);
	CHECK(kernel->rendered().rumbles_playing == 1);

	// A hit at the servo's impact cap: both motors full, for one I/O cycle before the release
	// (too short to catch by polling the kernel's state on a loaded machine: the uploads tell).
	REQUIRE(device->write_force(ForceCommand{ Vec3(0.0, 3.0, 0.0), Vec3(0.0, 3.0, 0.0) }) == DeviceIo::OK);
	CHECK(evdev_test::wait_until([&] {
		for (const ScriptedEvdevCall &call : evdev_test::ff_calls(kernel->calls())) {
			if (call.bytes.size() < 4) {
				continue;
			}
			// Whatever id the kernel gave the effect.
			const int16_t id = static_cast<int16_t>(call.bytes[2] | (call.bytes[3] << 8));
			if (id >= 0 && call.bytes == expected_rumble_effect(id, 0xffff, 0xffff)) {
				return true;
			}
		}
		return false;
	}));
	// Then it fades to silence.
	REQUIRE(device->write_force(ForceCommand{}) == DeviceIo::OK);
	CHECK(evdev_test::wait_until([&] { return kernel->rendered().rumble_weak == 0 && kernel->rendered().rumble_strong == 0; }));

	device->close();
	CHECK(kernel->effects_in_use() == 0);
	CHECK(kernel->open_fds() == 0);
	const std::vector<ScriptedEvdevCall> calls = evdev_test::ff_calls(kernel->calls());
	REQUIRE(calls.size() >= 2);
	CHECK(calls[calls.size() - 2].bytes == evdev_test::expected_event(EVDEV_EV_FF, 0, 0)); // Stopped,
	CHECK(calls.back().request == EVDEV_EVIOCRMFF); // then erased.
}
