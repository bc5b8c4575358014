// EvdevDevice over the scripted kernel: capabilities, the force reaching the firmware model
// through the I/O thread, the stick reaching read_state, close/unplug/error leaving the
// device at rest, the player-facing reasons; and the real syscalls on this machine.

#include "dev_tools/evdev/scripted_evdev_device.h"
#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_device.h"
#include "evdev_test_support.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <cmath>
#include <limits>
#include <string>

using namespace haptics;
using namespace haptics::evdev;
using Kind = ScriptedEvdevCall::Kind;

namespace {

std::string text(const Status &p_status) {
	return p_status.message();
}

// The last EVIOCSFF, stop write and EVIOCRMFF on p_fd, in order, must be: zero level,
// stop, erase, then close.
void check_left_at_rest(const std::vector<ScriptedEvdevCall> &p_calls, int p_fd, int16_t p_id) {
	std::vector<ScriptedEvdevCall> tail;
	for (const ScriptedEvdevCall &call : p_calls) {
		if (call.fd == p_fd && call.kind != Kind::READ &&
				(call.kind != Kind::IOCTL || call.request == EVDEV_EVIOCSFF || call.request == EVDEV_EVIOCRMFF)) {
			tail.push_back(call);
		}
	}
	REQUIRE(tail.size() >= 4);
	const size_t n = tail.size();
	CHECK(tail[n - 4].request == EVDEV_EVIOCSFF);
	CHECK(tail[n - 4].bytes == evdev_test::expected_constant_effect(p_id, 0, 0));
	CHECK(tail[n - 3].kind == Kind::WRITE);
	CHECK(tail[n - 3].bytes == evdev_test::expected_event(EVDEV_EV_FF, static_cast<uint16_t>(p_id), 0));
	CHECK(tail[n - 2].request == EVDEV_EVIOCRMFF);
	CHECK(tail[n - 2].bytes == evdev_test::int_bytes(p_id));
	CHECK(tail[n - 1].kind == Kind::CLOSE);
}

} // namespace

TEST_CASE("evdev device: joystick and wheel capabilities, names from EVIOCGNAME") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	DeviceCapabilities caps = device->capabilities();
	CHECK(caps.input_dof == 2);
	CHECK(caps.output_dof == 2);
	CHECK(caps.output == ForceOutput::DIRECTIONAL);
	CHECK(caps.native_rate_hz == 500.0);
	CHECK(caps.limits.max_force_n == 5.0);
	CHECK(caps.limits.max_continuous_force_n == 2.5);
	CHECK(caps.limits.workspace_radius_m == 0.05);
	CHECK(caps.physical);
	CHECK_FALSE(caps.needs_homing);
	CHECK(caps.button_count == 4);
	CHECK(std::string(device->name()) == "Arduino LLC Arduino Leonardo");
	CHECK(device->open().ok()); // Idempotent.
	device->close();

	auto wheel_kernel = std::make_shared<ScriptedEvdevKernel>(scripted_wheel_script());
	auto wheel = make_scripted_device(wheel_kernel);
	REQUIRE(wheel->open().ok());
	caps = wheel->capabilities();
	CHECK(caps.input_dof == 1);
	CHECK(caps.output_dof == 1);
	CHECK(caps.button_count == 2);
	CHECK(std::string(wheel->name()) == "Scripted FFB wheel");
}

TEST_CASE("evdev device: a servo force reaches the firmware model - the stick reaches read_state") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3(1.5, -2.0, 0.0), {} }) == DeviceIo::OK);
	CHECK(evdev_test::wait_until([&] { return kernel->rendered().axis_y > 0.39; }));
	const ScriptedRenderedForce rendered = kernel->rendered();
	CHECK(rendered.axis_x == doctest::Approx(0.3).epsilon(1e-3));
	CHECK(rendered.axis_y == doctest::Approx(0.4).epsilon(1e-3)); // Device down = axis +Y.

	kernel->set_stick_axes(-0.5, 0.5); // Left and pulled toward the user.
	kernel->set_button(0x121, true);
	kernel->sync();
	DeviceState state;
	CHECK(evdev_test::wait_until([&] { return device->read_state(state) == DeviceIo::OK && state.buttons == 0b10u; }));
	CHECK(state.position_m.x == doctest::Approx(-0.025).epsilon(1e-3));
	CHECK(state.position_m.y == doctest::Approx(-0.025).epsilon(1e-3));
	CHECK(state.position_m.z == 0.0);
	CHECK(state.ready);
}

TEST_CASE("evdev device: a held force is a finite effect played again before it ends") {
	// hid-pidff before 6.15 hands a length of 0 to the device's Duration, which firmwares read
	// as over at once: the effect lasts CONSTANT_EFFECT_LENGTH_MS and is renewed in time.
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3(1.0, 0.0, 0.0), {} }) == DeviceIo::OK);
	REQUIRE(evdev_test::wait_until([&] { return kernel->rendered().axis_x > 0.19; }));
	kernel->clear_calls();
	const auto plays = [&] {
		size_t count = 0;
		for (const ScriptedEvdevCall &call : evdev_test::ff_calls(kernel->calls())) {
			// A play: {EV_FF, the effect's id, 1}.
			const bool play = call.kind == Kind::WRITE && call.bytes == evdev_test::expected_event(EVDEV_EV_FF, call.bytes[18], 1);
			count += play ? 1 : 0;
		}
		return count;
	};
	// Three renewals take 0.75 s of the device's clock; a loaded machine gets 5 s.
	CHECK(evdev_test::wait_until([&] { return plays() >= 3; }, 5.0));
	for (const ScriptedEvdevCall &call : kernel->calls()) {
		if (call.kind == Kind::IOCTL && call.request == EVDEV_EVIOCSFF) {
			CHECK(call.bytes[10] + 256 * call.bytes[11] == CONSTANT_EFFECT_LENGTH_MS);
		}
	}
	device->close();
}

TEST_CASE("evdev device: the stick's position at open comes from EVIOCGABS (no event needed)") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	kernel->set_stick_axes(1.0, -1.0); // Before anyone opened: only EVIOCGABS knows.
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	DeviceState state;
	REQUIRE(device->read_state(state) == DeviceIo::OK);
	CHECK(state.position_m.x == doctest::Approx(0.05));
	CHECK(state.position_m.y == doctest::Approx(0.05));
}

TEST_CASE("evdev device: close leaves zero force, stopped, erased, fd closed") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3(4.0, 0.0, 0.0), {} }) == DeviceIo::OK);
	REQUIRE(evdev_test::wait_until([&] { return kernel->rendered().level > 0; }));
	device->close();
	CHECK_FALSE(device->is_open());
	CHECK(kernel->rendered().playing == 0);
	CHECK(kernel->effects_in_use() == 0);
	CHECK(kernel->open_fds() == 0);
	check_left_at_rest(kernel->calls(), 40, 0);
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::FAILED);
	device->close(); // Idempotent.
}

TEST_CASE("evdev device: unplug -> DISCONNECTED with a reason - reopen fails cleanly until replugged") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	kernel->set_plugged(false);
	DeviceState state;
	CHECK(evdev_test::wait_until([&] { return device->read_state(state) == DeviceIo::DISCONNECTED; }));
	const DeviceStatus status = device->status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(std::string(status.reason).rfind("/dev/input/event7 was unplugged (ENODEV while ", 0) == 0);
	CHECK(device->write_force({ Vec3(1.0, 0.0, 0.0), {} }) == DeviceIo::DISCONNECTED);
	CHECK(device->calibrate().code() == StatusCode::DEVICE_DISCONNECTED);
	device->close();
	CHECK(kernel->open_fds() == 0);

	const Status reopened = device->open();
	CHECK(reopened.code() == StatusCode::NO_DEVICE);
	CHECK(text(reopened) == "/dev/input/event7 is not present (ENOENT): the device is unplugged or the path is stale");
	kernel->set_plugged(true);
	REQUIRE(device->open().ok());
	CHECK(device->status().io == DeviceIo::OK);
	REQUIRE(device->read_state(state) == DeviceIo::OK);
}

TEST_CASE("evdev device: open() after an unplug, without close(), starts afresh on the new node") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	kernel->set_plugged(false);
	DeviceState state;
	REQUIRE(evdev_test::wait_until([&] { return device->read_state(state) == DeviceIo::DISCONNECTED; }));
	kernel->set_plugged(true);
	REQUIRE(device->open().ok());
	CHECK(device->status().io == DeviceIo::OK);
	CHECK(kernel->open_fds() == 1); // The dead fd was closed, a new one opened.
	CHECK(kernel->effects_in_use() == 1);
	CHECK(device->read_state(state) == DeviceIo::OK);
}

TEST_CASE("evdev device: another I/O error -> FAILED with strerror, and the device is left at rest") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	REQUIRE(device->write_force({ Vec3(0.0, 3.0, 0.0), {} }) == DeviceIo::OK);
	REQUIRE(evdev_test::wait_until([&] { return kernel->rendered().level > 0; }));
	kernel->fail_next_ioctl(EVDEV_EVIOCSFF, EIO);
	REQUIRE(device->write_force({ Vec3(0.0, 1.0, 0.0), {} }) == DeviceIo::OK);
	DeviceState state;
	CHECK(evdev_test::wait_until([&] { return device->read_state(state) == DeviceIo::FAILED; }));
	CHECK(std::string(device->status().reason) ==
			"/dev/input/event7: updating the force failed: Input/output error (EIO)");
	// Stopped and erased by the I/O thread already, before the game closes it.
	CHECK(kernel->rendered().playing == 0);
	CHECK(kernel->effects_in_use() == 0);
	device->close();
	CHECK(kernel->open_fds() == 0);
}

TEST_CASE("evdev device: non-finite or huge forces are never sent as such") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	auto device = make_scripted_device(kernel);
	REQUIRE(device->open().ok());
	const double nan = std::numeric_limits<double>::quiet_NaN();
	REQUIRE(device->write_force({ Vec3(1e9, 0.0, 0.0), {} }) == DeviceIo::OK);
	REQUIRE(evdev_test::wait_until([&] { return kernel->rendered().level == 0x7fff; }));
	REQUIRE(device->write_force({ Vec3(nan, nan, nan), {} }) == DeviceIo::OK);
	CHECK(evdev_test::wait_until([&] { return kernel->rendered().level == 0; }));
	device->close();
}

TEST_CASE("evdev device: open errors the player can act on") {
	ScriptedEvdevScript no_permission = scripted_joystick_script();
	no_permission.open_error = EACCES;
	auto kernel = std::make_shared<ScriptedEvdevKernel>(no_permission);
	Status status = make_scripted_device(kernel)->open();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(text(status) ==
			"no permission for /dev/input/event7: install the udev rule (tools/udev, see README Devices) or add yourself "
			"to the 'input' group");

	ScriptedEvdevScript gain_only = scripted_joystick_script();
	gain_only.ff_codes = { EVDEV_FF_GAIN };
	kernel = std::make_shared<ScriptedEvdevKernel>(gain_only);
	status = make_scripted_device(kernel)->open();
	CHECK(status.code() == StatusCode::UNSUPPORTED);
	CHECK(text(status) ==
			"the kernel driver offers neither constant force nor rumble on this device (/dev/input/event7: no FF_CONSTANT or "
			"FF_RUMBLE in EVIOCGBIT(EV_FF))");
	CHECK(kernel->open_fds() == 0);

	ScriptedEvdevScript no_axes = scripted_joystick_script();
	no_axes.axes = { { EVDEV_ABS_Y, AbsRange{ 0, -1, 1, 0, 0, 0 } } };
	kernel = std::make_shared<ScriptedEvdevKernel>(no_axes);
	status = make_scripted_device(kernel)->open();
	CHECK(text(status) == "/dev/input/event7: a joystick needs ABS_X and ABS_Y, the device lacks ABS_X");

	ScriptedEvdevScript flat_axis = scripted_joystick_script();
	flat_axis.axes[0].range = AbsRange{ 0, 100, 100, 0, 0, 0 };
	kernel = std::make_shared<ScriptedEvdevKernel>(flat_axis);
	status = make_scripted_device(kernel)->open();
	CHECK(text(status) == "/dev/input/event7: ABS_X range [100, 100] is empty");
	CHECK(kernel->open_fds() == 0);
	CHECK(kernel->effects_in_use() == 0);

	EvdevDeviceConfig bad;
	bad.max_continuous_force_n = 9.0;
	status = make_scripted_device(std::make_shared<ScriptedEvdevKernel>(), bad)->open();
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(text(status) == "evdev_device.max_continuous_force_n must be in (0, 5] (got 9)");
}

TEST_CASE("evdev device: a wheel config forced on a joystick-shaped node renders x only") {
	auto kernel = std::make_shared<ScriptedEvdevKernel>();
	EvdevDeviceConfig config;
	config.shape = EvdevShapeChoice::WHEEL; // A wheel with pedals on ABS_Y.
	auto device = make_scripted_device(kernel, config);
	REQUIRE(device->open().ok());
	CHECK(device->capabilities().input_dof == 1);
	REQUIRE(device->write_force({ Vec3(-2.5, 4.0, 0.0), {} }) == DeviceIo::OK);
	REQUIRE(evdev_test::wait_until([&] { return kernel->rendered().level != 0; }));
	CHECK(kernel->rendered().direction == 0x4000);
	CHECK(kernel->rendered().level == -16384);
	CHECK(kernel->rendered().axis_x == doctest::Approx(-0.5).epsilon(1e-3));
}

TEST_CASE("evdev probe: handled only for backend evdev - scripted EACCES and missing constant force") {
	DeviceInfo info;
	info.backend = "hidapi";
	info.path = "/dev/input/event7";
	CHECK_FALSE(probe(info).handled);
	info.backend = "evdev";
	ScriptedEvdevKernel kernel;
	DeviceAvailability availability = probe(info, kernel);
	CHECK(availability.handled);
	CHECK(availability.openable);
	CHECK(kernel.open_fds() == 0);

	ScriptedEvdevScript script = scripted_joystick_script();
	script.open_error = EACCES;
	ScriptedEvdevKernel locked(script);
	availability = probe(info, locked);
	CHECK_FALSE(availability.openable);
	CHECK(availability.reason.find("install the udev rule") != std::string::npos);
}

TEST_CASE("evdev real transport: /dev/input/event999 is a clean 'not present', never a crash") {
	DeviceInfo info;
	info.id = "evdev:test";
	info.backend = "evdev";
	info.path = "/dev/input/event999";
	std::unique_ptr<HapticDevice> device;
	const Status status = open_device(info, device);
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(text(status) == "/dev/input/event999 is not present (ENOENT): the device is unplugged or the path is stale");
	CHECK(device == nullptr);

	const DeviceAvailability availability = probe(info);
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	CHECK(availability.reason == text(status));

	info.backend = "libusb";
	CHECK(open_device(info, device).code() == StatusCode::INVALID_ARGUMENT);
	// A file that exists but is not an evdev node: the real ioctl answers ENOTTY.
	info.backend = "evdev";
	info.path = "/dev/null";
	const Status not_evdev = open_device(info, device);
	CHECK(not_evdev.code() == StatusCode::DEVICE_ERROR);
	CHECK(text(not_evdev) ==
			"/dev/null: EVIOCGBIT(EV_FF) failed: Inappropriate ioctl for device (ENOTTY); not an evdev node?");
}
