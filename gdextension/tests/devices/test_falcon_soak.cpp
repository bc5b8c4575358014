// The common backend soak (backend_soak.h) through the scripted Falcon: the 1 kHz servo
// renders a floor contact through FalconDevice's I/O thread, the cable is pulled and the
// servo must stop itself, the Falcon is plugged back (firmware again) and renders once more.

#include "backend_soak.h"
#include "dev_tools/falcon/scripted_falcon.h"
#include "dev_tools/falcon/scripted_falcon_device.h"
#include "devices/falcon/falcon_backend.h"
#include "devices/falcon/falcon_codec.h"
#include "devices/falcon/falcon_kinematics.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <memory>

using namespace haptics;
using namespace haptics::falcon;

TEST_CASE("falcon soak: servo loop through the scripted Falcon, unplug, replug") {
	ScriptedFalconOptions options;
	options.homing_commands = 5; // Homes a few ms into each session.
	auto model = std::make_shared<ScriptedFalcon>(options);
	// Below the workspace centre: pressing into the floor, whose normal is +y.
	model->set_device_position({ 0.0, -0.01, 0.0 });

	test::BackendSoakScript script;
	script.make_device = [&]() -> std::unique_ptr<HapticDevice> { return make_scripted_device(model); };
	script.unplug = [&] { model->unplug(); };
	script.replug = [&] { model->replug(); };
	HapticsSystem system;
	const test::BackendSoakResult result = test::run_backend_soak(system, script);

	REQUIRE(result.opened_first);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(result.device_status_after_unplug.io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(result.device_status_after_unplug.reason, "LIBUSB_ERROR_NO_DEVICE") != nullptr);
	REQUIRE(result.opened_again);
	CHECK(result.ticks_first >= static_cast<uint64_t>(0.6 * 1000.0 * script.seconds_each));
	CHECK(result.ticks_second >= static_cast<uint64_t>(0.6 * 1000.0 * script.seconds_each));
	CHECK(result.peak_total_force_n > 0.1);

	// What went over the (scripted) wire.
	const ScriptedFalconCounters counters = model->counters();
	const double seconds = result.seconds_first + result.seconds_second;
	const double wire_bytes_per_s = static_cast<double>(counters.bytes_written + counters.bytes_read) / seconds;
	const double command_rate = static_cast<double>(counters.commands) / seconds;
	MESSAGE("falcon soak: " << result.ticks_first << " + " << result.ticks_second << " servo ticks in " << seconds << " s; "
							<< counters.commands << " commands (" << command_rate << "/s), " << wire_bytes_per_s
							<< " bytes/s on the wire incl. two firmware uploads and FTDI status bytes");
	CHECK(command_rate > 500.0);

	// The floor pushed up: commands rendered the servo's force, +y, at the scripted position
	// (words -> force through the Jacobian: the inverse of what the device did).
	const std::vector<BulkRecord> writes = model->bulk_writes();
	bool pushed_up = false;
	Vec3 strongest;
	bool failed_after_unplug = false;
	for (const BulkRecord &write : writes) {
		failed_after_unplug = failed_after_unplug || write.result == usb::UsbResult::NO_DEVICE;
		FalconCommand command;
		if (write.result != usb::UsbResult::OK || !decode_falcon_command(write.bytes.data(), write.bytes.size(), command)) {
			continue;
		}
		Vec3 force;
		if (falcon_motor_words_to_force(FALCON_KINEMATIC_CENTRE + Vec3{ 0.0, -0.01, 0.0 }, command.torque, force) && length(force) > length(strongest)) {
			strongest = force;
		}
		if (falcon_motor_words_to_force(FALCON_KINEMATIC_CENTRE + Vec3{ 0.0, -0.01, 0.0 }, command.torque, force) && force.y > 0.5 * result.peak_total_force_n &&
				std::fabs(force.x) < 0.05 * force.y && std::fabs(force.z) < 0.05 * force.y) {
			pushed_up = true;
		}
	}
	MESSAGE("strongest force on the wire: (" << strongest.x << ", " << strongest.y << ", " << strongest.z << ") N, peak total " << result.peak_total_force_n);
	CHECK(pushed_up);
	CHECK(failed_after_unplug); // The I/O thread hit the unplug (and stopped there).
	// The last command on the wire, after stop and close: zero torques.
	REQUIRE(model->has_command());
	const FalconCommand last = model->last_command();
	CHECK(last.torque[0] == 0);
	CHECK(last.torque[1] == 0);
	CHECK(last.torque[2] == 0);
	REQUIRE_FALSE(writes.empty());
	CHECK(writes.back().bytes.size() == 16);
}
