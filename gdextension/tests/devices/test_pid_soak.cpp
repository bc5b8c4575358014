// The common backend soak (backend_soak.h) through the scripted AJ joystick: the 1 kHz servo
// renders a floor contact while the stick is pulled down into it, the joystick is unplugged
// mid-run (the servo must stop itself with DEVICE_DISCONNECTED and the transport's reason),
// plugged back, reopened, and rendering resumes. Then the wire record is checked.

#include "backend_soak.h"
#include "dev_tools/pid/scripted_pid_device.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/pid/pid_backend.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace haptics;
using namespace haptics::pid;

TEST_CASE("pid soak: servo at 1 kHz through the scripted AJ joystick, unplug, replug, reopen") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ, 65536);
	// HID Y +0.6 is the stick pulled toward the user: device y = -0.6 x 5 cm, into the floor.
	joystick->set_stick(0.0, 0.6);
	ScriptedForce force_before_unplug;
	HapticsSystem system;
	test::BackendSoakScript script;
	script.make_device = [&] { return make_scripted_device(joystick); };
	script.unplug = [&] {
		force_before_unplug = joystick->rendered_force();
		joystick->set_plugged(false);
	};
	script.replug = [&] { joystick->set_plugged(true); };
	script.contact_normal = Vec3{ 0.0, 1.0, 0.0 };

	const test::BackendSoakResult result = test::run_backend_soak(system, script);
	REQUIRE(result.opened_first);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(result.device_status_after_unplug.io == DeviceIo::DISCONNECTED);
	CHECK(std::string(result.device_status_after_unplug.reason).find("unplugged") != std::string::npos);
	REQUIRE(result.opened_again);
	// All ticks rendered: about 1000 per second, generous for a loaded 2-core machine.
	CHECK(result.ticks_first >= 600);
	CHECK(result.ticks_second >= 600);
	CHECK(result.peak_total_force_n > 0.1);
	// The floor pushed the stick up, i.e. away from the user: the firmware's -Y.
	CHECK(force_before_unplug.playing_effects == 1);
	CHECK(force_before_unplug.y < -0.02);
	CHECK(std::fabs(force_before_unplug.x) < 0.2 * std::fabs(force_before_unplug.y));

	const ScriptedJoystickStats stats = joystick->stats();
	const double seconds = result.seconds_first + result.seconds_second;
	MESSAGE("pid soak: ticks " << result.ticks_first << " + " << result.ticks_second << " in " << seconds << " s; host->device "
							   << static_cast<double>(stats.bytes_to_device) / seconds << " B/s in " << stats.outputs
							   << " output reports (" << static_cast<double>(stats.outputs) / seconds << "/s), device->host "
							   << static_cast<double>(stats.bytes_from_device) / seconds << " B/s; peak force "
							   << result.peak_total_force_n << " N");
	CHECK(stats.records_dropped == 0);
	CHECK(stats.pool_reads == 0);
	// Far below the 1 report/ms an interrupt OUT endpoint drains: only changes go out.
	CHECK(static_cast<double>(stats.outputs) / seconds < 600.0);

	// At the end: level 0, Stop, Block Free were the last reports; nothing plays.
	const std::vector<ScriptedTransfer> records = joystick->records();
	std::vector<std::vector<uint8_t>> outputs;
	for (const ScriptedTransfer &transfer : records) {
		if (transfer.kind == TransferKind::OUTPUT) {
			outputs.push_back(transfer.to_vector());
		}
	}
	REQUIRE(outputs.size() >= 3);
	CHECK(outputs[outputs.size() - 2] == std::vector<uint8_t>{ 0x0A, 0x01, 0x03, 0x01 });
	CHECK(outputs[outputs.size() - 1] == std::vector<uint8_t>{ 0x0B, 0x01 });
	const std::vector<uint8_t> *last_constant = nullptr;
	for (const std::vector<uint8_t> &report : outputs) {
		if (report[0] == 0x05) {
			last_constant = &report;
		}
	}
	REQUIRE(last_constant);
	CHECK(*last_constant == std::vector<uint8_t>{ 0x05, 0x01, 0x00, 0x00 });
	CHECK(joystick->rendered_force().playing_effects == 0);
	CHECK(joystick->allocated_effects() == 0);
}
