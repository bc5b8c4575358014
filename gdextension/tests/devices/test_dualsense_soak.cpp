// The DualSense through the whole servo: the common backend soak (backend_soak.h) over the
// scripted pad on USB and on Bluetooth, and an impact pushed through the engine reaching the
// pad's motors. Timing-tolerant bounds only; the figures are printed with MESSAGE.

#include "backend_soak.h"

#include "dev_tools/dualsense/scripted_dualsense_device.h"
#include "devices/dualsense/dualsense_backend.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>

namespace haptics::dualsense {

namespace {

void soak(Bus p_bus) {
	ScriptedDualSenseOptions options;
	options.bus = p_bus;
	auto pad = std::make_shared<ScriptedDualSense>(options);
	// Stick pushed "down": into the floor whose normal is (0, 1, 0), so the continuous force
	// is non-zero and the triggers resist.
	pad->set_stick_deflection(0.0, -0.8);

	HapticsSystem system;
	test::BackendSoakScript script;
	script.make_device = [&pad] { return make_scripted_device(pad); };
	script.unplug = [&pad] { pad->unplug(); };
	script.replug = [&pad] { pad->replug(); };
	const test::BackendSoakResult result = test::run_backend_soak(system, script);

	REQUIRE(result.opened_first);
	REQUIRE(result.opened_again);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(result.device_status_after_unplug.io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(result.device_status_after_unplug.reason, "DualSense disconnected") != nullptr);
	CHECK(static_cast<double>(result.ticks_first) >= 0.6 * 1000.0 * result.seconds_first);
	CHECK(static_cast<double>(result.ticks_second) >= 0.6 * 1000.0 * result.seconds_second);
	CHECK(result.peak_total_force_n > 0.1); // The floor pushed back...

	const ScriptedPadCounters counters = pad->counters();
	CHECK(counters.max_trigger_strength >= 1); // ...and the triggers felt it.
	CHECK(counters.reports_rejected == 0);
	CHECK(counters.sequence_errors == 0);
	CHECK(counters.input_reports > 100);
	// Last report: motors off, both triggers off.
	const ScriptedPadHeld held = pad->held();
	CHECK(held.motor_left == 0);
	CHECK(held.motor_right == 0);
	CHECK(held.right_trigger == trigger_off());
	CHECK(held.left_trigger == trigger_off());
	const size_t common_offset = p_bus == Bus::BLUETOOTH ? BT_COMMON_OFFSET : USB_COMMON_OFFSET;
	REQUIRE(held.last_report_size == (p_bus == Bus::BLUETOOTH ? BT_OUTPUT_SIZE : USB_OUTPUT_SIZE));
	CHECK(held.last_report[common_offset + common::MOTOR_RIGHT] == 0);
	CHECK(held.last_report[common_offset + common::MOTOR_LEFT] == 0);
	CHECK((held.last_report[common_offset + common::VALID_FLAG0] & (FLAG0_RIGHT_TRIGGER | FLAG0_LEFT_TRIGGER)) ==
			(FLAG0_RIGHT_TRIGGER | FLAG0_LEFT_TRIGGER));
	CHECK(held.last_report[common_offset + common::RIGHT_TRIGGER] == TRIGGER_MODE_OFF);
	CHECK(held.last_report[common_offset + common::LEFT_TRIGGER] == TRIGGER_MODE_OFF);

	const double seconds = result.seconds_first + result.seconds_second;
	MESSAGE("dualsense soak (", std::string(bus_name(p_bus)), "): ", result.ticks_first, " + ", result.ticks_second, " ticks in ",
			seconds, " s; pad: ", counters.reports_accepted, " reports (", static_cast<double>(counters.reports_accepted) / seconds,
			"/s, ", static_cast<double>(counters.bytes_accepted) / seconds, " B/s), ", counters.input_reports,
			" input reports, max trigger strength ", counters.max_trigger_strength, ", peak force ", result.peak_total_force_n,
			" N; reason after unplug: ", result.device_status_after_unplug.reason);
}

} // namespace

TEST_CASE("dualsense soak: USB through the servo, unplug, replug, motors and triggers off at the end") {
	soak(Bus::USB);
}

TEST_CASE("dualsense soak: Bluetooth through the servo (CRCs, sequence), unplug, replug, off at the end") {
	soak(Bus::BLUETOOTH);
}

TEST_CASE("dualsense system: a pushed impact reaches the pad's motors and dies away") {
	auto pad = std::make_shared<ScriptedDualSense>();
	HapticsSystem system;
	RenderConfig config = system.config();
	config.servo.safety.startup_ramp_s = 0.01;
	config.servo.safety.start_force_n = 0.0;
	REQUIRE(system.configure(config));
	REQUIRE(system.open_device(make_scripted_device(pad)));
	REQUIRE(system.start(1000.0));
	Frame frame;
	frame.sequence = 1;
	REQUIRE(system.submit_frame(frame));
	std::this_thread::sleep_for(std::chrono::milliseconds(50)); // Past the start-up ramp.

	const uint64_t before = pad->counters().reports_accepted;
	ImpactEvent impact;
	impact.direction = Vec3{ 0.0, 1.0, 0.0 };
	impact.speed_m_per_s = 6.0; // 0.5 N/(m/s) * 6 = 3 N: the cap, full scale.
	REQUIRE(system.push_impact(impact));
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (pad->counters().max_motor == 0 && std::chrono::steady_clock::now() < deadline) {
		++frame.sequence;
		system.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	CHECK(pad->counters().max_motor > 100);
	while (pad->held().motor_right != 0 && std::chrono::steady_clock::now() < deadline) {
		++frame.sequence;
		system.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
	}
	CHECK(pad->held().motor_right == 0);
	CHECK(pad->held().motor_left == 0);
	const uint64_t during = pad->counters().reports_accepted - before;
	system.stop();
	system.close_device();
	CHECK(pad->counters().reports_rejected == 0);
	MESSAGE("dualsense system impact: max motor ", pad->counters().max_motor, ", ", during,
			" reports from the hit to silence");
}

} // namespace haptics::dualsense
