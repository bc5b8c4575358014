// HdDevice against the fake libHD, through the real loader: the exact call sequences of
// docs/devices/openhaptics.md (open, each scheduler tick, close), every per-tick get/set inside one frame,
// units (mm -> m centred, mm/s -> m/s, N unchanged), axes, orientation, buttons, and the
// force guard at the boundary (continuous cap, peak cap, non-finite -> zero).

#include "devices/openhaptics/openhaptics_backend.h"
#include "openhaptics_fake.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::openhaptics;
using haptics::test::FakeHd;
using haptics::test::fresh_fake_hd;
using haptics::test::wait_for;

namespace {

struct Expected {
	const char *name;
	unsigned int pname;
};

bool is(const FakeHdCall &p_call, const char *p_name) {
	return std::strcmp(p_call.name, p_name) == 0;
}

std::vector<FakeHdCall> game_thread_calls(const FakeHd &p_fake) {
	std::vector<FakeHdCall> result;
	for (const FakeHdCall &call : p_fake.calls()) {
		if (!call.on_scheduler) {
			result.push_back(call);
		}
	}
	return result;
}

void check_sequence(const std::vector<FakeHdCall> &p_calls, size_t p_first, const std::vector<Expected> &p_expected) {
	REQUIRE(p_calls.size() >= p_first + p_expected.size());
	for (size_t i = 0; i < p_expected.size(); ++i) {
		const FakeHdCall &call = p_calls[p_first + i];
		INFO("call ", p_first + i, ": expected ", std::string(p_expected[i].name), " got ", std::string(call.name));
		CHECK(std::string(call.name) == p_expected[i].name);
		CHECK(call.pname == p_expected[i].pname);
	}
}

// The handle the fake returned for our servo callback.
unsigned long servo_handle(const FakeHd &p_fake) {
	for (const FakeHdCall &call : p_fake.calls()) {
		if (is(call, "hdScheduleAsynchronous")) {
			return static_cast<unsigned long>(call.values[0]);
		}
	}
	return 0;
}

std::unique_ptr<HdDevice> open_fake_device(FakeHd &r_fake, HdDeviceOptions p_options = {}) {
	auto device = make_device_on_runtime(haptics::test::fake_hd_path(), std::move(p_options));
	const Status opened = device->open();
	INFO(opened.message());
	REQUIRE(opened);
	REQUIRE(r_fake.wait_ticks(3, 2000));
	return device;
}

// Writes p_command, then waits until the fake saw it set (a few ticks).
Vec3 force_set_for(FakeHd &r_fake, HdDevice &r_device, const ForceCommand &p_command) {
	REQUIRE(r_device.write_force(p_command) == DeviceIo::OK);
	REQUIRE(r_fake.wait_ticks(3, 2000));
	double force[3];
	r_fake.last_force(force);
	return Vec3{ force[0], force[1], force[2] };
}

} // namespace

TEST_CASE("openhaptics: open follows docs/devices/openhaptics.md: init, check, current, query, enable, schedule, rate, start") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	const std::vector<FakeHdCall> calls = game_thread_calls(fake);
	check_sequence(calls, 0,
			{
					{ "hdInitDevice", 0 }, // HD_DEFAULT_DEVICE (null)
					{ "hdGetError", 0 },
					{ "hdMakeCurrentDevice", 0 },
					{ "hdGetString", HD_DEVICE_MODEL_TYPE },
					{ "hdGetString", HD_DEVICE_VENDOR },
					{ "hdGetString", HD_DEVICE_SERIAL_NUMBER },
					{ "hdGetString", HD_DEVICE_DRIVER_VERSION },
					{ "hdGetDoublev", HD_NOMINAL_MAX_FORCE },
					{ "hdGetDoublev", HD_NOMINAL_MAX_CONTINUOUS_FORCE },
					{ "hdGetDoublev", HD_NOMINAL_MAX_STIFFNESS },
					{ "hdGetDoublev", HD_USABLE_WORKSPACE_DIMENSIONS },
					{ "hdGetIntegerv", HD_INPUT_DOF },
					{ "hdGetIntegerv", HD_OUTPUT_DOF },
					{ "hdGetIntegerv", HD_CALIBRATION_STYLE },
					{ "hdGetError", 0 },
					{ "hdEnable", HD_FORCE_OUTPUT },
					{ "hdScheduleAsynchronous", HD_MAX_SCHEDULER_PRIORITY },
					{ "hdSetSchedulerRate", 0 },
					{ "hdStartScheduler", 0 },
					{ "hdGetError", 0 },
					{ "hdScheduleSynchronous", HD_MAX_SCHEDULER_PRIORITY },
			});
	CHECK(calls[17].values[0] == 1000.0); // hdSetSchedulerRate(1000)
	CHECK(calls.size() == 21); // Nothing else on the game thread while it runs.

	// The calibration check ran on HD's thread, inside the synchronous callback.
	const unsigned long sync = static_cast<unsigned long>(calls[20].values[0]);
	std::vector<std::string> in_sync;
	for (const FakeHdCall &call : fake.calls()) {
		if (call.callback == sync) {
			CHECK(call.on_scheduler);
			in_sync.push_back(call.name);
		}
	}
	CHECK(in_sync == std::vector<std::string>{ "hdCheckCalibration", "hdGetError" });

	// What the query gave.
	const DeviceCapabilities capabilities = device->capabilities();
	CHECK(capabilities.input_dof == 6);
	CHECK(capabilities.has_orientation);
	CHECK(capabilities.output_dof == 3);
	CHECK(capabilities.output == ForceOutput::DIRECTIONAL);
	CHECK(capabilities.limits.max_force_n == 3.3);
	CHECK(capabilities.limits.max_continuous_force_n == 0.88);
	CHECK(capabilities.limits.max_stiffness_n_per_m == doctest::Approx(1260.0)); // 1.26 N/mm
	CHECK(capabilities.limits.workspace_radius_m == doctest::Approx(0.050));
	CHECK(capabilities.native_rate_hz == 1000.0);
	CHECK(capabilities.physical);
	CHECK(capabilities.needs_homing);
	CHECK(capabilities.button_count == 2);
	CHECK(std::string(device->name()) == "Touch");
	CHECK(device->report().vendor == "3D Systems");
	CHECK(device->report().serial == "FAKE-0001");
	CHECK(device->report().driver_version == "fake 1.0");
	CHECK(device->report().calibration_style == HD_CALIBRATION_INKWELL);
	device->close();
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: each scheduler tick reads and sets everything inside one frame, in order") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	REQUIRE(fake.wait_ticks(20, 2000));
	device->close();
	const unsigned long servo = servo_handle(fake);
	REQUIRE(servo != 0);

	// Group the servo callback's calls by scheduler tick.
	std::vector<std::vector<FakeHdCall>> ticks;
	unsigned long long tick = 0;
	for (const FakeHdCall &call : fake.calls()) {
		if (call.callback != servo) {
			continue;
		}
		CHECK(call.on_scheduler);
		if (ticks.empty() || call.tick != tick) {
			ticks.emplace_back();
			tick = call.tick;
		}
		ticks.back().push_back(call);
	}
	REQUIRE(ticks.size() >= 20);
	const std::vector<Expected> expected = {
		{ "hdGetCurrentDevice", 0 },
		{ "hdBeginFrame", 0 },
		{ "hdGetDoublev", HD_CURRENT_POSITION },
		{ "hdGetDoublev", HD_CURRENT_VELOCITY },
		{ "hdGetDoublev", HD_CURRENT_TRANSFORM },
		{ "hdGetIntegerv", HD_CURRENT_BUTTONS },
		{ "hdSetDoublev", HD_CURRENT_FORCE },
		{ "hdEndFrame", 0 },
		{ "hdGetError", 0 },
	};
	// Until the device reports HD_CALIBRATION_OK (the opening ticks, before open()'s own
	// check ran) a tick starts with hdCheckCalibration, outside the frame as in ROS's driver.
	size_t calibrating_ticks = 0;
	for (std::vector<FakeHdCall> &calls : ticks) {
		if (!calls.empty() && is(calls.front(), "hdCheckCalibration")) {
			CHECK_FALSE(calls.front().in_frame);
			calls.erase(calls.begin());
			++calibrating_ticks;
		}
		CHECK(calls.size() == expected.size());
		check_sequence(calls, 0, expected);
		for (const FakeHdCall &call : calls) {
			if (std::strncmp(call.name, "hdGet", 5) == 0 && !is(call, "hdGetError") && !is(call, "hdGetCurrentDevice")) {
				CHECK(call.in_frame);
			}
			if (std::strncmp(call.name, "hdSet", 5) == 0) {
				CHECK(call.in_frame);
			}
		}
	}
	CHECK(calibrating_ticks < 5);
	// And every frame parameter anywhere was used inside a frame (the fake counts misuse).
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: close sets zero force on HD's thread, then stops, unschedules and disables") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	const Vec3 pushing = force_set_for(fake, *device, ForceCommand{ { 0.0, 0.5, 0.0 }, {} });
	REQUIRE(pushing.y == doctest::Approx(0.5));
	const size_t before_close = game_thread_calls(fake).size();
	device->close();
	CHECK_FALSE(device->is_open());
	CHECK_FALSE(fake.scheduler_running());

	const std::vector<FakeHdCall> calls = game_thread_calls(fake);
	check_sequence(calls, before_close,
			{
					{ "hdScheduleSynchronous", HD_MAX_SCHEDULER_PRIORITY },
					{ "hdStopScheduler", 0 },
					{ "hdUnschedule", static_cast<unsigned int>(servo_handle(fake)) },
					{ "hdDisableDevice", 0 },
					{ "hdGetError", 0 }, // Drained: the next open starts clean.
			});
	// The last force set before hdDisableDevice is zero, set inside a frame.
	const std::vector<FakeHdCall> all = fake.calls();
	const FakeHdCall *last_force = nullptr;
	for (const FakeHdCall &call : all) {
		if (is(call, "hdDisableDevice")) {
			break;
		}
		if (is(call, "hdSetDoublev") && call.pname == HD_CURRENT_FORCE) {
			last_force = &call;
		}
	}
	REQUIRE(last_force != nullptr);
	CHECK(last_force->in_frame);
	CHECK(last_force->values[0] == 0.0);
	CHECK(last_force->values[1] == 0.0);
	CHECK(last_force->values[2] == 0.0);

	// Closed: the servo side says so; a second close calls nothing.
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::FAILED);
	const size_t after_close = fake.call_count();
	device->close();
	CHECK(fake.call_count() == after_close);
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: positions mm -> m from the workspace centre, velocity m/s, buttons, orientation") {
	FakeHd &fake = fresh_fake_hd();
	const double position_mm[3] = { 30.0, -10.0, 50.0 }; // Centre is (0, 10, 10) mm.
	const double velocity_mm_s[3] = { 100.0, -200.0, 300.0 };
	const double about_y[16] = { 0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 30, -10, 50, 1 }; // 90 deg about +y
	fake.set_doubles(HD_CURRENT_POSITION, position_mm, 3);
	fake.set_doubles(HD_CURRENT_VELOCITY, velocity_mm_s, 3);
	fake.set_doubles(HD_CURRENT_TRANSFORM, about_y, 16);
	fake.set_integer(HD_CURRENT_BUTTONS, 0x3); // HD_DEVICE_BUTTON_1 | _2
	auto device = open_fake_device(fake);

	DeviceState state;
	REQUIRE(device->read_state(state) == DeviceIo::OK);
	CHECK(state.ready);
	// Same axes as ours (x right, y up, z toward the user): no swaps, no sign flips.
	CHECK(state.position_m.x == doctest::Approx(0.030));
	CHECK(state.position_m.y == doctest::Approx(-0.020));
	CHECK(state.position_m.z == doctest::Approx(0.040));
	CHECK(state.velocity_m_per_s.x == doctest::Approx(0.1));
	CHECK(state.velocity_m_per_s.y == doctest::Approx(-0.2));
	CHECK(state.velocity_m_per_s.z == doctest::Approx(0.3));
	CHECK(state.orientation.w == doctest::Approx(std::sqrt(0.5)));
	CHECK(state.orientation.y == doctest::Approx(std::sqrt(0.5)));
	CHECK(state.buttons == 0x3u);

	// A new script shows up within a few ticks: the state is live, not read once.
	const double moved_mm[3] = { 0.0, 10.0, 10.0 };
	fake.set_doubles(HD_CURRENT_POSITION, moved_mm, 3);
	fake.set_integer(HD_CURRENT_BUTTONS, 0);
	REQUIRE(fake.wait_ticks(3, 2000));
	REQUIRE(device->read_state(state) == DeviceIo::OK);
	CHECK(length(state.position_m) < 1e-12);
	CHECK(state.buttons == 0u);
	device->close();
}

TEST_CASE("openhaptics: forces go out in newtons on the same axes") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	const Vec3 set = force_set_for(fake, *device, ForceCommand{ { 0.1, -0.2, 0.3 }, {} });
	CHECK(set == Vec3{ 0.1, -0.2, 0.3 });
	const Vec3 up = force_set_for(fake, *device, ForceCommand{ { 0.0, 0.7, 0.0 }, {} });
	CHECK(up == Vec3{ 0.0, 0.7, 0.0 });
	device->close();
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: the continuous share is capped at HD_NOMINAL_MAX_CONTINUOUS_FORCE, the total at the peak") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	const Vec3 continuous = force_set_for(fake, *device, ForceCommand{ { 2.0, 0.0, 0.0 }, {} });
	CHECK(continuous.x == doctest::Approx(0.88));
	const Vec3 with_impact = force_set_for(fake, *device, ForceCommand{ { 0.0, -3.0, 0.0 }, { 0.0, -2.0, 0.0 } });
	CHECK(with_impact.y == doctest::Approx(-2.88));
	const Vec3 peak = force_set_for(fake, *device, ForceCommand{ { 0.0, 0.0, 10.0 }, { 0.0, 0.0, 10.0 } });
	CHECK(peak.z == doctest::Approx(3.3));
	device->close();

	// Without the continuous cap only the peak bounds it.
	HdDeviceOptions options;
	options.clamp_continuous_to_rating = false;
	auto uncapped = open_fake_device(fake, options);
	CHECK(force_set_for(fake, *uncapped, ForceCommand{ { 2.0, 0.0, 0.0 }, {} }).x == doctest::Approx(2.0));
	CHECK(force_set_for(fake, *uncapped, ForceCommand{ { 9.0, 0.0, 0.0 }, {} }).x == doctest::Approx(3.3));
	uncapped->close();
	CHECK(fake.misuse_count() == 0); // Never above HD_NOMINAL_MAX_FORCE, never non-finite.
}

TEST_CASE("openhaptics: a non-finite command goes out as zero force and is counted") {
	FakeHd &fake = fresh_fake_hd();
	auto device = open_fake_device(fake);
	REQUIRE(force_set_for(fake, *device, ForceCommand{ { 0.3, 0.0, 0.0 }, {} }).x == doctest::Approx(0.3));
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	CHECK(force_set_for(fake, *device, ForceCommand{ { nan, 0.1, 0.0 }, {} }) == Vec3{});
	CHECK(force_set_for(fake, *device, ForceCommand{ { 0.1, 0.0, 0.0 }, { 0.0, inf, 0.0 } }) == Vec3{});
	CHECK(device->non_finite_commands() == 2);
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::OK); // Not a device fault: rendering goes on.
	device->close();
	CHECK(fake.misuse_count() == 0);
}

TEST_CASE("openhaptics: scheduler rate out of range is refused before anything loads") {
	FakeHd &fake = fresh_fake_hd();
	HdDeviceOptions options;
	options.scheduler_rate_hz = 100;
	auto device = make_device_on_runtime(haptics::test::fake_hd_path(), options);
	const Status status = device->open();
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::strstr(status.message(), "scheduler_rate_hz") != nullptr);
	CHECK(fake.call_count() == 0);
}
