// HdDevice's failure paths against the fake libHD: hdInitDevice failing (HD_INVALID_HANDLE
// + error), nonsense device parameters, HD_COMM_ERROR mid-run (unplugged -> DISCONNECTED),
// another HD error inside the callback (its 12-byte struct -> FAILED with code, name, text),
// a non-finite or impossibly far position, calibration (inkwell), and a second device pre-empting the first.
// Each leaves the backend closed or disabled with a Status that says why; none crashes.

#include "devices/openhaptics/openhaptics_backend.h"
#include "openhaptics_fake.h"

#include <doctest/doctest.h>

#include <cstring>
#include <limits>
#include <string>

using namespace haptics;
using namespace haptics::openhaptics;
using haptics::test::FakeHd;
using haptics::test::fresh_fake_hd;
using haptics::test::wait_for;

namespace {

bool contains(const char *p_text, const char *p_part) {
	return std::strstr(p_text, p_part) != nullptr;
}

size_t count_calls(const FakeHd &p_fake, const char *p_name) {
	size_t count = 0;
	for (const FakeHdCall &call : p_fake.calls()) {
		count += std::strcmp(call.name, p_name) == 0 ? 1 : 0;
	}
	return count;
}

std::unique_ptr<HdDevice> fake_device() {
	return make_device_on_runtime(haptics::test::fake_hd_path());
}

// Opens, then waits until the servo side stops reading OK (the callback failed).
DeviceIo run_until_failure(HdDevice &r_device) {
	DeviceIo io = DeviceIo::OK;
	wait_for([&] {
		DeviceState state;
		io = r_device.read_state(state);
		return io != DeviceIo::OK;
	});
	return io;
}

// The fake must end every failure with a usable device: a fresh open works.
void check_reopens(FakeHd &r_fake) {
	auto again = fake_device();
	const Status reopened = again->open();
	INFO(reopened.message());
	CHECK(reopened);
	again->close();
	CHECK(r_fake.misuse_count() == 0);
	if (r_fake.misuse_count() != 0) {
		MESSAGE(r_fake.first_misuse());
	}
}

} // namespace

TEST_CASE("openhaptics: hdInitDevice failing leaves the backend closed, with the HD error in the Status") {
	FakeHd &fake = fresh_fake_hd();
	fake.fail_init(HD_DEVICE_FAULT, 7);
	auto device = fake_device();
	const Status status = device->open();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(contains(status.message(), "hdInitDevice(HD_DEFAULT_DEVICE)"));
	CHECK(contains(status.message(), "HD error 0x0300 (HD_DEVICE_FAULT)"));
	CHECK(contains(status.message(), "internal error 7"));
	CHECK_FALSE(device->is_open());
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::FAILED);
	// Nothing after the failed init: no enable, no scheduler, no disable of a device never had.
	CHECK(count_calls(fake, "hdEnable") == 0);
	CHECK(count_calls(fake, "hdStartScheduler") == 0);
	CHECK(count_calls(fake, "hdDisableDevice") == 0);
	CHECK_FALSE(fake.scheduler_running());
	check_reopens(fake);
}

TEST_CASE("openhaptics: opening an unplugged device is NO_DEVICE naming HD_COMM_ERROR") {
	FakeHd &fake = fresh_fake_hd();
	fake.set_unplugged(1);
	auto device = fake_device();
	const Status status = device->open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(contains(status.message(), "HD_COMM_ERROR"));
	CHECK_FALSE(device->is_open());
	fake.set_unplugged(0);
	check_reopens(fake);
}

TEST_CASE("openhaptics: nonsense device parameters refuse the open, naming the parameter") {
	struct Case {
		const char *what;
		unsigned int pname;
		double values[6];
		int count;
		StatusCode code;
	};
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const Case cases[] = {
		{ "HD_NOMINAL_MAX_FORCE", HD_NOMINAL_MAX_FORCE, { nan }, 1, StatusCode::DEVICE_ERROR },
		{ "HD_NOMINAL_MAX_FORCE", HD_NOMINAL_MAX_FORCE, { -1.0 }, 1, StatusCode::DEVICE_ERROR },
		{ "HD_NOMINAL_MAX_CONTINUOUS_FORCE", HD_NOMINAL_MAX_CONTINUOUS_FORCE, { 0.0 }, 1, StatusCode::DEVICE_ERROR },
		{ "HD_USABLE_WORKSPACE_DIMENSIONS: x", HD_USABLE_WORKSPACE_DIMENSIONS, { 80, -50, -40, -80, 70, 60 }, 6,
				StatusCode::DEVICE_ERROR },
		{ "HD_USABLE_WORKSPACE_DIMENSIONS: z", HD_USABLE_WORKSPACE_DIMENSIONS, { -80, -50, nan, 80, 70, 60 }, 6,
				StatusCode::DEVICE_ERROR },
	};
	for (const Case &bad : cases) {
		FakeHd &fake = fresh_fake_hd();
		fake.set_doubles(bad.pname, bad.values, bad.count);
		auto device = fake_device();
		const Status status = device->open();
		INFO(bad.what, " -> ", std::string(status.message()));
		CHECK(status.code() == bad.code);
		CHECK(contains(status.message(), bad.what));
		CHECK_FALSE(device->is_open());
		CHECK(count_calls(fake, "hdDisableDevice") == 1); // Initialised, so disabled again.
		CHECK(count_calls(fake, "hdStartScheduler") == 0);
	}
	FakeHd &fake = fresh_fake_hd();
	fake.set_integer(HD_OUTPUT_DOF, 1);
	auto device = fake_device();
	const Status status = device->open();
	CHECK(status.code() == StatusCode::UNSUPPORTED);
	CHECK(contains(status.message(), "HD_OUTPUT_DOF 1"));
	fake.set_integer(HD_OUTPUT_DOF, 3);
	check_reopens(fake);
}

TEST_CASE("openhaptics: missing strings give the default name, not a crash") {
	FakeHd &fake = fresh_fake_hd();
	fake.set_string(HD_DEVICE_MODEL_TYPE, nullptr);
	fake.set_string(HD_DEVICE_SERIAL_NUMBER, nullptr);
	auto device = fake_device();
	REQUIRE(device->open());
	CHECK(std::string(device->name()) == "OpenHaptics device");
	CHECK(device->report().serial.empty());
	device->close();
}

TEST_CASE("openhaptics: HD_COMM_ERROR mid-run (unplugged) disconnects with the HD reason and zero force") {
	FakeHd &fake = fresh_fake_hd();
	auto device = fake_device();
	REQUIRE(device->open());
	REQUIRE(device->write_force(ForceCommand{ { 0.0, 0.6, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(fake.wait_ticks(5, 2000));
	fake.set_unplugged(1);
	CHECK(run_until_failure(*device) == DeviceIo::DISCONNECTED);
	const DeviceStatus status = device->status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(contains(status.reason, "HD error 0x0302 (HD_COMM_ERROR)"));
	CHECK(device->write_zero() == DeviceIo::DISCONNECTED);

	// The callback returned HD_CALLBACK_DONE after one more frame that set zero.
	double force[3];
	fake.last_force(force);
	CHECK(force[0] == 0.0);
	CHECK(force[1] == 0.0);
	CHECK(force[2] == 0.0);
	const unsigned long long sets = fake.force_sets();
	REQUIRE(fake.wait_ticks(5, 2000));
	CHECK(fake.force_sets() == sets);

	device->close();
	CHECK(count_calls(fake, "hdUnschedule") == 0); // HD already dropped the finished callback.
	CHECK(device->status().io == DeviceIo::DISCONNECTED); // close keeps the reason.
	fake.set_unplugged(0);
	check_reopens(fake);
}

TEST_CASE("openhaptics: an HD error struct inside the callback fails the device with code, name and text") {
	FakeHd &fake = fresh_fake_hd();
	auto device = fake_device();
	REQUIRE(device->open());
	REQUIRE(device->write_force(ForceCommand{ { 0.0, 0.6, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(fake.wait_ticks(3, 2000));
	double pushing[3];
	fake.last_force(pushing);
	REQUIRE(pushing[1] == doctest::Approx(0.6));
	fake.inject_error(0x0201, 123, 0); // docs/devices/openhaptics.md's 3-int struct
	CHECK(run_until_failure(*device) == DeviceIo::FAILED);
	CHECK(std::string(device->status().reason) ==
			"HD error 0x0201 (HD_EXCEEDED_MAX_FORCE): fake: the force exceeded the device's maximum, internal error 123");
	double force[3];
	fake.last_force(force);
	CHECK(force[1] == 0.0);
	device->close();
	check_reopens(fake);
}

TEST_CASE("openhaptics: a non-finite position from the runtime fails the device, naming it") {
	FakeHd &fake = fresh_fake_hd();
	auto device = fake_device();
	REQUIRE(device->open());
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double position[3] = { 0.0, nan, 0.0 };
	fake.set_doubles(HD_CURRENT_POSITION, position, 3);
	CHECK(run_until_failure(*device) == DeviceIo::FAILED);
	CHECK(contains(device->status().reason, "HD_CURRENT_POSITION"));
	device->close();
	check_reopens(fake);
}

TEST_CASE("openhaptics: a position beyond any workspace fails the device like a non-finite one, naming it") {
	FakeHd &fake = fresh_fake_hd();
	auto device = fake_device();
	REQUIRE(device->open());
	const double position_mm[3] = { 0.0, 0.0, 1.0e6 }; // 1 km: garbage, not a stylus.
	fake.set_doubles(HD_CURRENT_POSITION, position_mm, 3);
	CHECK(run_until_failure(*device) == DeviceIo::FAILED);
	const std::string reason = device->status().reason.str();
	CHECK(reason.starts_with("OpenHaptics: the device reported an HD_CURRENT_POSITION 1e+03 m from the workspace centre"));
	CHECK(reason.ends_with("(no device reaches 10 m)"));
	device->close();
	check_reopens(fake);
}

TEST_CASE("openhaptics: a device needing the inkwell is open but not ready, then ready once it is in") {
	FakeHd &fake = fresh_fake_hd();
	fake.set_calibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
	auto device = fake_device();
	REQUIRE(device->open());
	REQUIRE(fake.wait_ticks(3, 2000));
	DeviceState state;
	REQUIRE(device->read_state(state) == DeviceIo::OK);
	CHECK_FALSE(state.ready); // The servo holds zero force, and so does the device.
	REQUIRE(device->write_force(ForceCommand{ { 0.5, 0.0, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(fake.wait_ticks(3, 2000));
	double force[3];
	fake.last_force(force);
	CHECK(force[0] == 0.0);
	const DeviceStatus status = device->status();
	CHECK(status.io == DeviceIo::OK);
	CHECK(contains(status.reason, "put the stylus in the inkwell"));
	const Status calibrated = device->calibrate();
	CHECK(calibrated.code() == StatusCode::DEVICE_ERROR);
	CHECK(contains(calibrated.message(), "inkwell"));

	// The stylus goes into the inkwell: HD now wants an update, which the callback runs.
	fake.set_calibration(HD_CALIBRATION_NEEDS_UPDATE);
	CHECK(wait_for([&] { return device->read_state(state) == DeviceIo::OK && state.ready; }));
	CHECK(device->status().reason[0] == '\0');
	REQUIRE(fake.wait_ticks(3, 2000));
	fake.last_force(force);
	CHECK(force[0] == doctest::Approx(0.5)); // Calibrated: the command goes out.
	bool updated_with_inkwell = false;
	for (const FakeHdCall &call : fake.calls()) {
		if (std::strcmp(call.name, "hdUpdateCalibration") == 0) {
			updated_with_inkwell = call.pname == static_cast<unsigned int>(HD_CALIBRATION_INKWELL) && call.on_scheduler;
		}
	}
	CHECK(updated_with_inkwell);
	device->close();
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: calibrate() runs hdUpdateCalibration on HD's thread - NEEDS_UPDATE at open is updated") {
	FakeHd &fake = fresh_fake_hd();
	fake.set_integer(HD_CALIBRATION_STYLE, HD_CALIBRATION_ENCODER_RESET | HD_CALIBRATION_AUTO);
	fake.set_calibration(HD_CALIBRATION_NEEDS_UPDATE);
	auto device = fake_device();
	CHECK(device->calibrate().code() == StatusCode::NO_DEVICE); // Not open yet.
	REQUIRE(device->open());
	CHECK(device->report().calibration_style == HD_CALIBRATION_AUTO); // Preferred over reset.
	DeviceState state;
	CHECK(wait_for([&] { return device->read_state(state) == DeviceIo::OK && state.ready; }));
	CHECK(count_calls(fake, "hdUpdateCalibration") == 1);
	CHECK(device->calibrate());
	CHECK(count_calls(fake, "hdUpdateCalibration") == 2);
	for (const FakeHdCall &call : fake.calls()) {
		if (std::strcmp(call.name, "hdUpdateCalibration") == 0) {
			CHECK(call.on_scheduler);
			CHECK(call.pname == static_cast<unsigned int>(HD_CALIBRATION_AUTO));
		}
	}
	device->close();
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: opening a second device closes the first (one HD scheduler per process)") {
	FakeHd &fake = fresh_fake_hd();
	auto first = fake_device();
	REQUIRE(first->open());
	auto second = fake_device();
	REQUIRE(second->open());
	CHECK_FALSE(first->is_open());
	CHECK(first->status().io == DeviceIo::FAILED);
	CHECK(contains(first->status().reason, "another OpenHaptics device was opened"));
	DeviceState state;
	CHECK(first->read_state(state) == DeviceIo::FAILED);
	CHECK(wait_for([&] { return second->read_state(state) == DeviceIo::OK && state.ready; }));
	first->close(); // A no-op now; must not touch the second device's session.
	CHECK(fake.scheduler_running());
	CHECK(second->is_open());
	second.reset(); // The destructor closes.
	CHECK_FALSE(fake.scheduler_running());
	CHECK(count_calls(fake, "hdInitDevice") == 2);
	CHECK(count_calls(fake, "hdDisableDevice") == 2);
	CHECK(fake.misuse_count() == 0);
}
