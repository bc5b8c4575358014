// PidDevice end to end over the scripted firmware: what opening sends, a rendered force
// arriving at the firmware with the right direction (both firmwares), the stick deflection
// as the position, only changed values on the wire, unplug, clean open failures, and the
// force mapping itself.

#include "dev_tools/pid/scripted_pid_device.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/pid/pid_backend.h"
#include "devices/pid/pid_device.h"
#include "devices/pid/pid_force_mapping.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

using namespace haptics;
using namespace haptics::pid;
using Bytes = std::vector<uint8_t>;

namespace {

// Polls p_condition for up to 2 s (the I/O thread runs at 250 Hz on a loaded machine).
bool eventually(const std::function<bool()> &p_condition) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (std::chrono::steady_clock::now() < deadline) {
		if (p_condition()) {
			return true;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	return p_condition();
}

std::vector<Bytes> outputs(const ScriptedPidJoystick &p_joystick) {
	std::vector<Bytes> result;
	for (const ScriptedTransfer &transfer : p_joystick.records()) {
		if (transfer.kind == TransferKind::OUTPUT) {
			result.push_back(transfer.to_vector());
		}
	}
	return result;
}

// The firmware's force per HID axis back in device space (y up = -HID Y), newtons.
Vec3 firmware_force_n(const ScriptedPidJoystick &p_joystick, double p_max_force_n) {
	const ScriptedForce force = p_joystick.rendered_force();
	return Vec3{ force.x * p_max_force_n, -force.y * p_max_force_n, 0.0 };
}

} // namespace

TEST_CASE("pid device: opening an AJ stick sends the init sequence, creates and starts the effect - close frees it") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	std::unique_ptr<HapticDevice> device = make_scripted_device(joystick);
	REQUIRE(device->open().ok());
	const DeviceCapabilities capabilities = device->capabilities();
	CHECK(capabilities.input_dof == 2);
	CHECK(capabilities.output_dof == 2);
	CHECK(capabilities.output == ForceOutput::DIRECTIONAL);
	CHECK(capabilities.limits.max_force_n == 4.0);
	CHECK(capabilities.limits.max_continuous_force_n == 2.0);
	CHECK(capabilities.native_rate_hz == 250.0);
	CHECK(capabilities.button_count == 16);
	CHECK(capabilities.physical);
	const std::vector<Bytes> opened = outputs(*joystick);
	REQUIRE(opened.size() == 8);
	CHECK(opened[0] == Bytes{ 0x0C, 0x04 }); // Reset
	CHECK(opened[1] == Bytes{ 0x0C, 0x04 }); // Reset
	CHECK(opened[2] == Bytes{ 0x0C, 0x03 }); // Stop All
	CHECK(opened[3] == Bytes{ 0x0C, 0x01 }); // Enable Actuators
	CHECK(opened[4] == Bytes{ 0x0D, 0xFF }); // Gain
	// Set Effect, direction 0, AJ's infinite 0x7FFF; level 0; Start.
	CHECK(opened[5] == Bytes{ 0x01, 0x01, 0x01, 0xFF, 0x7F, 0x00, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00 });
	CHECK(opened[6] == Bytes{ 0x05, 0x01, 0x00, 0x00 });
	CHECK(opened[7] == Bytes{ 0x0A, 0x01, 0x01, 0x01 });
	CHECK(joystick->allocated_effects() == 1);
	CHECK(joystick->effect(1).duration_infinite);
	CHECK(joystick->effect(1).playing);

	REQUIRE(device->write_force({ Vec3{ 2.0, 0.0, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(eventually([&] { return joystick->effect(1).magnitude != 0; }));
	joystick->clear_records();
	device->close();
	CHECK_FALSE(device->is_open());
	// io_stop: level 0 then Stop; close: Block Free.
	CHECK(outputs(*joystick) == std::vector<Bytes>{ { 0x05, 0x01, 0x00, 0x00 }, { 0x0A, 0x01, 0x03, 0x01 }, { 0x0B, 0x01 } });
	CHECK(joystick->allocated_effects() == 0);
	CHECK(joystick->rendered_force().playing_effects == 0);
	CHECK(joystick->stats().pool_reads == 0);
	device->close(); // Idempotent, and silent.
	CHECK(joystick->records().size() == 3);
}

TEST_CASE("pid device: the rendered force reaches the firmware with its direction (AJ, AJ with a Start Delay, OFB-like)") {
	for (const ScriptedFirmware firmware : { ScriptedFirmware::AJ, ScriptedFirmware::AJ_START_DELAY, ScriptedFirmware::VIRTUAL }) {
		CAPTURE(static_cast<int>(firmware));
		auto joystick = std::make_shared<ScriptedPidJoystick>(firmware);
		std::unique_ptr<HapticDevice> device = make_scripted_device(joystick);
		REQUIRE(device->open().ok());
		const double max_force = device->limits().max_force_n;
		// AJ's direction has 256 steps (1.4°): allow that much of the magnitude sideways.
		const double tolerance = 0.03 * max_force;
		const Vec3 forces[] = { { 2.0, 0.0, 0.0 }, { 0.0, 2.0, 0.0 }, { -1.0, -1.0, 0.0 }, { 0.0, -3.0, 0.0 }, { -2.5, 1.0, 0.0 },
			{ 1.5, 0.0, 0.0 } };
		for (const Vec3 &force : forces) {
			CAPTURE(force.x);
			CAPTURE(force.y);
			REQUIRE(device->write_force({ force, {} }) == DeviceIo::OK);
			const bool arrived = eventually([&] {
				const Vec3 rendered = firmware_force_n(*joystick, max_force);
				return std::fabs(rendered.x - force.x) < tolerance && std::fabs(rendered.y - force.y) < tolerance;
			});
			const Vec3 rendered = firmware_force_n(*joystick, max_force);
			CHECK_MESSAGE(arrived, "firmware renders (" << rendered.x << ", " << rendered.y << ") N");
		}
		// Beyond the limit: full scale, not more; NaN: zero.
		REQUIRE(device->write_force({ Vec3{ 0.0, 100.0, 0.0 }, {} }) == DeviceIo::OK);
		CHECK(eventually([&] { return std::fabs(joystick->rendered_force().y + 1.0) < 1e-3; }));
		const double nan = std::numeric_limits<double>::quiet_NaN();
		REQUIRE(device->write_force({ Vec3{ nan, 1.0, 0.0 }, {} }) == DeviceIo::OK);
		CHECK(eventually([&] { return joystick->rendered_force().y == 0.0 && joystick->rendered_force().x == 0.0; }));
		device->close();
	}
}

TEST_CASE("pid device: the stick deflection is the position and the buttons come through") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	joystick->set_stick(0.5, -0.25); // Right, and pushed away from the user.
	joystick->set_buttons(0x8005);
	PidDeviceConfig config;
	config.workspace_radius_m = 0.04;
	std::unique_ptr<HapticDevice> device = make_scripted_device(joystick, config);
	REQUIRE(device->open().ok());
	DeviceState state;
	REQUIRE(eventually([&] { return device->read_state(state) == DeviceIo::OK && state.buttons == 0x8005; }));
	CHECK(state.position_m.x == doctest::Approx(0.5 * 0.04).epsilon(1e-4));
	CHECK(state.position_m.y == doctest::Approx(0.25 * 0.04).epsilon(1e-4)); // Away from the user = up.
	CHECK(state.position_m.z == 0.0);
	CHECK(state.ready);
	joystick->set_stick(-1.0, 1.0);
	joystick->set_buttons(0);
	REQUIRE(eventually([&] { return device->read_state(state) == DeviceIo::OK && state.buttons == 0; }));
	CHECK(state.position_m.x == doctest::Approx(-0.04));
	CHECK(state.position_m.y == doctest::Approx(-0.04));
	auto *pid_device = static_cast<PidDevice *>(device.get());
	CHECK(pid_device->counters().input_reports > 0);
	CHECK(eventually([&] { return pid_device->counters().other_input_reports > 0; })); // PID State, skipped.
	device->close();
}

TEST_CASE("pid device: a wheel (no Y axis) is 1-DOF and renders only the x component at 90°") {
	auto wheel = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::VIRTUAL_WHEEL);
	wheel->set_stick(-0.5, 0.9); // The firmware reports no Y.
	std::unique_ptr<HapticDevice> device = make_scripted_device(wheel);
	REQUIRE(device->open().ok());
	CHECK(device->capabilities().input_dof == 1);
	CHECK(device->capabilities().output_dof == 1);
	CHECK(std::string(device->name()) == "Scripted PID wheel (OFB-like)");
	DeviceState state;
	REQUIRE(eventually([&] { return device->read_state(state) == DeviceIo::OK && state.position_m.x < 0.0; }));
	CHECK(state.position_m.x == doctest::Approx(-0.5 * 0.05).epsilon(1e-3));
	CHECK(state.position_m.y == 0.0);
	REQUIRE(device->write_force({ Vec3{ -2.0, 3.0, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(eventually([&] { return wheel->effect(1).magnitude != 0; }));
	CHECK(wheel->effect(1).direction == 9000); // +X, centidegrees
	CHECK(wheel->rendered_force().x == doctest::Approx(-0.5).epsilon(1e-3));
	CHECK(wheel->rendered_force().y == doctest::Approx(0.0).epsilon(1e-6));
	device->close();
}

TEST_CASE("pid device: a steady force puts nothing on the wire - the periodic restart does") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	PidDeviceConfig config;
	config.restart_interval_s = 0.1;
	std::unique_ptr<HapticDevice> device = make_scripted_device(joystick, config);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3{ 1.0, 1.0, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(eventually([&] { return joystick->effect(1).magnitude != 0; }));
	std::this_thread::sleep_for(std::chrono::milliseconds(20));
	joystick->clear_records();
	std::this_thread::sleep_for(std::chrono::milliseconds(350));
	const std::vector<Bytes> sent = outputs(*joystick);
	// Only restarts (Effect Operation Start), about one per 0.1 s: generous bounds.
	CHECK(sent.size() >= 1);
	CHECK(sent.size() <= 8);
	for (const Bytes &report : sent) {
		CHECK(report == Bytes{ 0x0A, 0x01, 0x01, 0x01 });
	}
	device->close();
}

TEST_CASE("pid device: unplugging stops the I/O with DISCONNECTED and a reason - replug and reopen works") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	std::unique_ptr<HapticDevice> device = make_scripted_device(joystick);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3{ 0.0, 1.0, 0.0 }, {} }) == DeviceIo::OK);
	joystick->set_plugged(false);
	DeviceState state;
	REQUIRE(eventually([&] { return device->read_state(state) == DeviceIo::DISCONNECTED; }));
	CHECK(device->write_force({}) == DeviceIo::DISCONNECTED);
	const DeviceStatus status = device->status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(std::string(status.reason).find("the device was unplugged (ENODEV)") != std::string::npos);
	joystick->clear_records();
	device->close(); // No I/O to a device that is gone.
	CHECK(joystick->records().empty());

	const Status refused = device->open();
	CHECK(refused.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::string(refused.message()).find("cannot open 'Scripted PID joystick (AJ firmware)'") != std::string::npos);
	joystick->set_plugged(true); // Power-on state: nothing allocated.
	CHECK(joystick->allocated_effects() == 0);
	REQUIRE(device->open().ok());
	CHECK(joystick->allocated_effects() == 1);
	device->close();
}

namespace {

// The scripted transport, but its OUT endpoint can be halted: writes then fail as a STALL
// does, and clear_halt() notes what the device's status said when the repair began.
class HaltingTransport final : public hid::HidTransport {
public:
	explicit HaltingTransport(std::shared_ptr<ScriptedPidJoystick> p_joystick) :
			inner_(make_scripted_transport(std::move(p_joystick))) {}

	Status open() override { return inner_->open(); }
	void close() override { inner_->close(); }
	bool is_open() const override { return inner_->is_open(); }
	Status report_descriptor(std::vector<uint8_t> &r_bytes) override { return inner_->report_descriptor(r_bytes); }
	DeviceIo write_output(std::span<const uint8_t> p_report) override {
		if (halted) {
			pending_ = true;
			return DeviceIo::FAILED;
		}
		return inner_->write_output(p_report);
	}
	DeviceIo send_feature(std::span<const uint8_t> p_report) override { return inner_->send_feature(p_report); }
	DeviceIo get_feature(std::span<uint8_t> p_buffer, size_t &r_length) override {
		return inner_->get_feature(p_buffer, r_length);
	}
	DeviceIo read_input(std::span<uint8_t> p_buffer, size_t &r_length) override {
		return inner_->read_input(p_buffer, r_length);
	}
	const char *last_error() const override {
		return !halted ? inner_->last_error() : repaired_ ? "endpoint stalled; reset it, reopening"
														  : "endpoint stalled; resetting it";
	}
	bool clear_halt() override {
		if (!pending_ || device == nullptr) {
			return false;
		}
		status_at_repair = device->status();
		pending_ = false;
		repaired_ = true;
		return true;
	}

	std::atomic<bool> halted{ false };
	const HapticDevice *device = nullptr;
	DeviceStatus status_at_repair;

private:
	std::unique_ptr<hid::HidTransport> inner_;
	bool pending_ = false;
	bool repaired_ = false;
};

} // namespace

TEST_CASE("pid device: a stalled endpoint is in the status before the slow repair starts, and the repair after it") {
	auto joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	auto owned = std::make_unique<HaltingTransport>(joystick);
	HaltingTransport &transport = *owned;
	PidDevice device(std::move(owned), "halting stick");
	transport.device = &device;
	REQUIRE(device.open().ok());
	REQUIRE(device.write_force({ Vec3{ 0.0, 1.0, 0.0 }, {} }) == DeviceIo::OK);
	transport.halted = true;
	(void)device.write_force({ Vec3{ 0.5, 0.5, 0.0 }, {} }); // A new force needs a report.
	DeviceState state;
	REQUIRE(eventually([&] { return device.read_state(state) == DeviceIo::FAILED; }));
	REQUIRE(eventually([&] { return std::string(device.status().reason).find("reopening") != std::string::npos; }));
	CHECK(transport.status_at_repair.io == DeviceIo::FAILED);
	CHECK(std::string(transport.status_at_repair.reason) == "PID stick: force update failed: endpoint stalled; resetting it");
	CHECK(std::string(device.status().reason) == "PID stick: force update failed: endpoint stalled; reset it, reopening");
	device.close();
}

TEST_CASE("pid device: open failures are clean and explained") {
	auto full = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::VIRTUAL);
	full->script_block_load(BlockLoadAnswer::FULL);
	std::unique_ptr<HapticDevice> device = make_scripted_device(full);
	Status status = device->open();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::string(status.message()) ==
			"cannot open 'Scripted PID joystick (OFB-like)': PID device has no free effect slot (Block Load: Full)");
	CHECK_FALSE(device->is_open());
	PidDeviceConfig bad;
	bad.io_rate_hz = 5000.0;
	status = make_scripted_device(nullptr, bad)->open();
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::string(status.message()).find("pid_device.io_rate_hz") != std::string::npos);
	bad = PidDeviceConfig{};
	bad.max_force_n = std::numeric_limits<double>::infinity();
	CHECK(make_scripted_device(nullptr, bad)->open().code() == StatusCode::INVALID_ARGUMENT);
}

TEST_CASE("pid force mapping: device space to the firmwares' X = sin θ, Y = -cos θ") {
	const PidForceMapping mapping;
	struct Case {
		Vec3 force;
		uint16_t direction;
		int16_t level;
	};
	const Case cases[] = {
		{ { 0.0, 4.0, 0.0 }, 0x0000, 0x7FFF }, // up: push the stick away (-Y)
		{ { 4.0, 0.0, 0.0 }, 0x4000, 0x7FFF }, // right: +X, Linux 90°
		{ { 0.0, 2.0, 0.0 }, 0x0000, 0x4000 },
		{ { 0.0, -2.0, 0.0 }, 0x0000, -0x4000 }, // down: same line, negative level
	};
	for (const Case &c : cases) {
		const PidForce force = map_force(c.force, mapping, 0);
		CHECK(force.direction == c.direction);
		CHECK(force.level == c.level);
	}
	// Left from a fresh start (previous 0 = up): 270° is 90° away, so sent as is.
	PidForce left = map_force({ -4.0, 0.0, 0.0 }, mapping, 0);
	CHECK(left.direction == 0xC000);
	CHECK(left.level == 0x7FFF);
	// Left after right: the same line, so the direction stays and the level turns negative.
	left = map_force({ -4.0, 0.0, 0.0 }, mapping, 0x4000);
	CHECK(left.direction == 0x4000);
	CHECK(left.level == -0x7FFF);
	// A force that quantises to zero keeps the previous direction; NaN is zero.
	CHECK(map_force({ 1e-9, 0.0, 0.0 }, mapping, 0x1234).direction == 0x1234);
	CHECK(map_force({ 1e-9, 0.0, 0.0 }, mapping, 0x1234).level == 0);
	CHECK(map_force({ std::nan(""), 1.0, 0.0 }, mapping, 0x1234).level == 0);
	// Clamped to full scale.
	CHECK(map_force({ 0.0, 400.0, 0.0 }, mapping, 0).level == 0x7FFF);
	// Round trip for any direction.
	for (int degrees = 0; degrees < 360; degrees += 15) {
		const double radians = degrees * std::numbers::pi / 180.0;
		const Vec3 force{ 3.0 * std::sin(radians), 3.0 * std::cos(radians), 0.0 };
		const Vec3 back = force_from_pid(map_force(force, mapping, 0x2000), mapping);
		CHECK(back.x == doctest::Approx(force.x).epsilon(1e-3));
		CHECK(back.y == doctest::Approx(force.y).epsilon(1e-3));
	}
	// Wheel: x only, direction fixed at +X; invert flags flip the axes.
	PidForceMapping wheel;
	wheel.wheel = true;
	const PidForce steer = map_force({ -2.0, 3.0, 0.0 }, wheel, 0);
	CHECK(steer.direction == PID_DIRECTION_PLUS_X);
	CHECK(steer.level == -0x4000);
	PidForceMapping inverted;
	inverted.invert_x = true;
	CHECK(map_force({ 4.0, 0.0, 0.0 }, inverted, 0).direction == 0xC000);
}
