// FalconDevice against the scripted Falcon: open with and without firmware, the axis
// mapping with explicit vectors, homing (ready, LED colours, zero torques until homed),
// forces on the wire, zero torques on close / NaN, unplug, silence, and a transport that
// reports more bytes than the read buffer holds.

#include "dev_tools/falcon/scripted_falcon.h"
#include "dev_tools/falcon/scripted_falcon_device.h"
#include "devices/falcon/falcon_axes.h"
#include "devices/falcon/falcon_backend.h"
#include "devices/falcon/falcon_codec.h"
#include "devices/falcon/falcon_device.h"
#include "devices/falcon/falcon_ftdi.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>

using namespace haptics;
using namespace haptics::falcon;

namespace {

// Polls until p_done or ~2 s; the I/O thread runs at 1 kHz.
bool eventually(const std::function<bool()> &p_done) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (std::chrono::steady_clock::now() < deadline) {
		if (p_done()) {
			return true;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	return p_done();
}

DeviceState state_of(FalconDevice &r_device) {
	DeviceState state;
	REQUIRE(r_device.read_state(state) == DeviceIo::OK);
	return state;
}

bool near(const Vec3 &p_a, const Vec3 &p_b, double p_tolerance) {
	return length(p_a - p_b) < p_tolerance;
}

std::shared_ptr<ScriptedFalcon> homed_model() {
	auto model = std::make_shared<ScriptedFalcon>();
	model->set_homed(FALCON_HOMED_ALL);
	return model;
}

} // namespace

TEST_CASE("falcon device: opening a fresh Falcon uploads the firmware, then runs at 1 kHz") {
	auto model = std::make_shared<ScriptedFalcon>();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	const Status opened = device->open();
	REQUIRE_MESSAGE(opened, opened.message());
	CHECK(device->is_open());
	CHECK(device->firmware_uploaded());
	CHECK(device->firmware_report().bytes_sent == 7914);
	CHECK(model->uploaded_image() == make_test_firmware_image());
	CHECK(device->open()); // Idempotent.
	CHECK(eventually([&] { return device->io_counters().frames > 20; }));
	CHECK(std::strcmp(device->name(), "Novint Falcon") == 0);

	const DeviceCapabilities capabilities = device->capabilities();
	CHECK(capabilities.input_dof == 3);
	CHECK(capabilities.output_dof == 3);
	CHECK(capabilities.output == ForceOutput::DIRECTIONAL);
	CHECK(capabilities.needs_homing);
	CHECK(capabilities.physical);
	CHECK(capabilities.button_count == 4);
	CHECK(capabilities.native_rate_hz == 1000.0);
	CHECK(capabilities.limits.max_force_n == 8.0);
	CHECK(capabilities.limits.max_continuous_force_n == 4.0);
	CHECK(capabilities.limits.workspace_radius_m == 0.04);
	device->close();
	CHECK_FALSE(device->is_open());
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::FAILED);
}

TEST_CASE("falcon device: a Falcon already running firmware is not re-flashed and needs no file") {
	ScriptedFalconOptions options;
	options.firmware_loaded = true;
	auto model = std::make_shared<ScriptedFalcon>(options);
	FalconDeviceConfig config; // No image, no file.
	std::unique_ptr<FalconDevice> device = make_scripted_device(model, config);
	REQUIRE(device->open());
	CHECK_FALSE(device->firmware_uploaded());
	for (const BulkRecord &write : model->bulk_writes()) {
		CHECK(write.bytes.size() == 16); // Only normal-mode commands: no 0A 43 0D, no 'A'.
	}
	// NIF's open(): purge RX, purge TX, then normal mode.
	const std::vector<ControlRecord> controls = model->control_transfers();
	REQUIRE(controls.size() >= 6);
	CHECK(controls[0].value == 0x0001);
	CHECK(controls[1].value == 0x0002);
	CHECK(controls[2].request == 0x09);
	CHECK(controls[2].value == 1);
	CHECK(controls[3].request == 0x03);
	CHECK(controls[3].value == 0x0002);
}

TEST_CASE("falcon device: without firmware and without a file, open() says what to set") {
	auto model = std::make_shared<ScriptedFalcon>();
	FalconDeviceConfig config;
	config.firmware_probe_attempts = 3;
	std::unique_ptr<FalconDevice> device = make_scripted_device(model, config);
	Status status = device->open();
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "set HAPTICS_FALCON_FIRMWARE to Novint's firmware file (not shipped with this game)") != nullptr);
	CHECK_FALSE(device->is_open());
	config.firmware_path = "/nonexistent/falcon.bin";
	device = make_scripted_device(model, config);
	status = device->open();
	CHECK(std::strstr(status.message(), "'/nonexistent/falcon.bin' not found") != nullptr);
	model->unplug();
	status = make_scripted_device(model)->open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(status.message(), "not present") != nullptr);
}

TEST_CASE("falcon device: axis mapping, grip pushed right reads +x, up +y, pulled out +z") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	struct Case {
		Vec3 kinematic;
		Vec3 device;
	};
	const Case cases[] = {
		{ { 0.0, 0.0, 0.125 }, { 0.0, 0.0, 0.0 } }, // Workspace centre.
		{ { 0.02, 0.0, 0.125 }, { 0.02, 0.0, 0.0 } }, // Pushed right.
		{ { 0.0, 0.03, 0.125 }, { 0.0, 0.03, 0.0 } }, // Up.
		{ { 0.0, 0.0, 0.160 }, { 0.0, 0.0, 0.035 } }, // Pulled out toward the user.
		{ { -0.025, -0.015, 0.100 }, { -0.025, -0.015, -0.025 } },
	};
	for (const Case &c : cases) {
		CAPTURE(c.device.x);
		CAPTURE(c.device.y);
		CAPTURE(c.device.z);
		model->set_position(c.kinematic);
		// Encoders are whole counts: ~0.06 mm per count per leg.
		CHECK(eventually([&] { return near(state_of(*device).position_m, c.device, 3e-4); }));
	}
	// Device-space scripting goes through the same mapping.
	model->set_device_position({ 0.01, -0.02, 0.005 });
	CHECK(eventually([&] { return near(state_of(*device).position_m, { 0.01, -0.02, 0.005 }, 3e-4); }));
	model->set_buttons(FALCON_BUTTON_1_PLUS | FALCON_BUTTON_4_MINUS);
	CHECK(eventually([&] { return state_of(*device).buttons == 0x9u; }));
}

TEST_CASE("falcon device: velocity is estimated from successive positions") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	CHECK(eventually([&] { return state_of(*device).ready; }));
	// Move right at 0.05 m/s for 0.3 s. On a loaded machine this thread may sleep for tens of
	// milliseconds, and the position then jumps within one of the device's frames: the
	// estimate spikes (rightly) for what it saw. Its mean over the motion does not: a low-pass
	// filter keeps the mean of what it is given, the distance over the time.
	constexpr double SPEED = 0.05;
	const auto start = std::chrono::steady_clock::now();
	double sum_vx = 0.0;
	int samples = 0;
	while (true) {
		const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
		if (t > 0.3) {
			break;
		}
		model->set_device_position({ -0.01 + SPEED * t, 0.0, 0.0 });
		if (t > 0.05) { // The filter (40 Hz) has settled.
			sum_vx += state_of(*device).velocity_m_per_s.x;
			++samples;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	REQUIRE(samples > 0);
	CHECK(sum_vx / samples == doctest::Approx(SPEED).epsilon(0.5));
	CHECK(eventually([&] { return std::fabs(state_of(*device).velocity_m_per_s.x) < 0.002; })); // At rest again.
}

TEST_CASE("falcon device: not homed -> not ready, red LED, homing flag, zero torques whatever the servo asks") {
	ScriptedFalconOptions options;
	options.homing_commands = -1; // Only set_homed() homes it.
	auto model = std::make_shared<ScriptedFalcon>(options);
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	CHECK(device->write_force({ { 0.0, 3.0, 0.0 }, {} }) == DeviceIo::OK);
	CHECK(eventually([&] { return model->counters().commands > 50; }));
	CHECK_FALSE(state_of(*device).ready);
	FalconCommand command = model->last_command();
	CHECK(command.flags == (FALCON_FLAG_HOMING | FALCON_LED_RED));
	CHECK(command.torque[0] == 0);
	CHECK(command.torque[1] == 0);
	CHECK(command.torque[2] == 0);
	CHECK(device->calibrate().code() == StatusCode::DEVICE_ERROR);
	CHECK(std::strstr(device->calibrate().message(), "pull the grip all the way out, then push it in") != nullptr);

	model->set_homed(0x3); // Two of three: still not homed.
	CHECK(eventually([&] { return model->counters().commands > 100; }));
	CHECK_FALSE(state_of(*device).ready);

	model->set_homed(FALCON_HOMED_ALL);
	CHECK(eventually([&] { return state_of(*device).ready; }));
	CHECK(device->calibrate());
	CHECK(eventually([&] { return model->last_command().flags == (FALCON_FLAG_HOMING | FALCON_LED_GREEN); }));
	CHECK(eventually([&] { return model->last_command().torque[0] != 0; }));
}

TEST_CASE("falcon device: the force on the wire is the servo's force, in device axes") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	const Vec3 positions[] = { { 0.0, 0.0, 0.0 }, { 0.015, -0.02, 0.01 } };
	const Vec3 forces[] = { { 2.0, 0.0, 0.0 }, { 0.0, 3.0, 0.0 }, { 0.0, 0.0, -1.5 }, { -1.0, 2.0, 0.5 } };
	for (const Vec3 &position : positions) {
		model->set_device_position(position);
		CHECK(eventually([&] { return near(state_of(*device).position_m, position, 3e-4); }));
		for (const Vec3 &force : forces) {
			CAPTURE(force.x);
			CAPTURE(force.y);
			CAPTURE(force.z);
			REQUIRE(device->write_force({ force, {} }) == DeviceIo::OK);
			// The words are whole numbers and the torques use the position from the encoders:
			// a few mN of error.
			CHECK(eventually([&] { return near(model->last_force_device(), force, 0.02); }));
		}
	}
}

TEST_CASE("falcon device: a NaN force sends zero torques and is counted") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	REQUIRE(device->write_force({ { 0.0, 2.0, 0.0 }, {} }) == DeviceIo::OK);
	CHECK(eventually([&] { return model->last_command().torque[0] != 0; }));
	const double nan = std::numeric_limits<double>::quiet_NaN();
	REQUIRE(device->write_force({ { nan, 2.0, 0.0 }, {} }) == DeviceIo::OK);
	CHECK(eventually([&] { return device->io_counters().torque_failures > 0; }));
	const FalconCommand command = model->last_command();
	CHECK(command.torque[0] == 0);
	CHECK(command.torque[1] == 0);
	CHECK(command.torque[2] == 0);
}

TEST_CASE("falcon device: close() leaves zero torques as the last command on the wire") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	REQUIRE(device->write_force({ { 1.0, 4.0, 0.0 }, {} }) == DeviceIo::OK);
	CHECK(eventually([&] { return model->last_command().torque[1] != 0; }));
	device->close();
	const FalconCommand command = model->last_command();
	CHECK(command.torque[0] == 0);
	CHECK(command.torque[1] == 0);
	CHECK(command.torque[2] == 0);
	const std::vector<BulkRecord> writes = model->bulk_writes();
	REQUIRE_FALSE(writes.empty());
	CHECK(writes.back().bytes ==
			std::vector<uint8_t>{ 0x3C, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x44, 0x41, 0x3E });
}

TEST_CASE("falcon device: unplugged -> DISCONNECTED with the USB error - replugged -> reopens, re-flashing") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	model->unplug();
	DeviceState state;
	CHECK(eventually([&] { return device->read_state(state) == DeviceIo::DISCONNECTED; }));
	CHECK(device->write_force({ { 0.0, 1.0, 0.0 }, {} }) == DeviceIo::DISCONNECTED);
	const DeviceStatus status = device->status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(status.reason, "LIBUSB_ERROR_NO_DEVICE") != nullptr);
	device->close();
	model->replug();
	REQUIRE(device->open());
	CHECK(device->firmware_uploaded()); // Power was lost with the cable: firmware again.
	CHECK(eventually([&] { return device->read_state(state) == DeviceIo::OK && state.ready; }));
}

TEST_CASE("falcon device: a Falcon that stops answering fails after the silence timeout") {
	auto model = homed_model();
	FalconDeviceConfig config = scripted_device_config();
	config.silence_timeout_s = 0.05;
	std::unique_ptr<FalconDevice> device = make_scripted_device(model, config);
	REQUIRE(device->open());
	model->replug(); // A power glitch: back in its loader, which ignores the commands.
	DeviceState state;
	CHECK(eventually([&] { return device->read_state(state) == DeviceIo::FAILED; }));
	CHECK(std::strstr(device->status().reason, "Falcon stopped answering") != nullptr);
}

TEST_CASE("falcon device: a read claiming more bytes than its buffer fails the device, nothing read past it") {
	auto model = homed_model();
	std::unique_ptr<FalconDevice> device = make_scripted_device(model);
	REQUIRE(device->open());
	ScriptedFalconOptions lying;
	lying.overstated_read_bytes = FTDI_PACKET_SIZE; // 64-byte reads reported as up to 128.
	model->set_options(lying);
	DeviceState state;
	CHECK(eventually([&] { return device->read_state(state) == DeviceIo::FAILED; }));
	CHECK(std::string(device->status().reason) ==
			"Falcon USB read failed: LIBUSB_ERROR_OVERFLOW (the transfer claimed more bytes than its buffer holds)");
}
