// The facade in manual-step mode: validation with named parameters and last-good-state,
// telemetry layout, determinism, drops, unplugging and device replacement.

#include "core/servo/telemetry.h"
#include "renderers/movement/force_model.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace haptics;

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double DT = 0.001;

bool mentions(const Status &p_status, const char *p_text) {
	return std::strstr(p_status.message(), p_text) != nullptr;
}

// Rigid hand at i = (0.3, -0.5, 0), floor contact, k = 2, b = 1, everything exact.
void set_up(HapticsSystem &r_system) {
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(r_system.open_simulated_device(device));
	REQUIRE(r_system.set_hand_target({ 0.03, -0.05, 0.0 }));
	REQUIRE(reconfigure(r_system, [](RenderConfig &c) {
		c.movement.force_model = ForceModelConfig{};
		c.servo.input.dead_zone = 0.0;
	}));
	REQUIRE(reconfigure(r_system, [](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ false, 13.0 }; }));
	SafetyConfig safety;
	safety.startup_ramp_s = 0.0;
	safety.slew_rate_n_per_s = 0.0;
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.servo.safety = safety; }));
}

Frame floor_frame() {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	return frame;
}

} // namespace

TEST_CASE("system: calls without a device fail cleanly") {
	HapticsSystem system;
	CHECK(system.step(DT).code() == StatusCode::NO_DEVICE);
	CHECK(system.start().code() == StatusCode::NO_DEVICE);
	CHECK(system.set_hand_target({}).code() == StatusCode::NO_DEVICE);
	CHECK(system.calibrate().code() == StatusCode::NO_DEVICE);
	CHECK_FALSE(system.is_running());
	CHECK(std::strcmp(system.device_name(), "") == 0);
	CHECK(system.submit_frame(floor_frame())); // Frames may arrive before a device.
	system.stop();
	system.close_device();
}

TEST_CASE("system: manual step renders the hand-computed forces") {
	HapticsSystem system;
	set_up(system);
	REQUIRE(system.submit_frame(floor_frame()));
	REQUIRE(system.step(DT));
	const ForceComponents f = system.forces();
	CHECK(system.input_vector().x == doctest::Approx(0.3));
	CHECK(system.input_vector().y == doctest::Approx(-0.5));
	CHECK(f.parts[NORMAL_FORCE].y == doctest::Approx(1.0));
	CHECK(f.parts[FRICTION_FORCE].x == doctest::Approx(-0.3));
	CHECK(f.total.x == doctest::Approx(-0.3));
	CHECK(f.total.y == doctest::Approx(1.0));
	const ServoStats stats = system.stats();
	CHECK(stats.scheduler == SchedulerKind::MANUAL);
	CHECK(stats.ticks == 1);
	CHECK(stats.frames_received == 1);
	CHECK(stats.frame_age_s == 0.0);
}

TEST_CASE("system: a NaN frame is rejected by name and the last good frame stays") {
	HapticsSystem system;
	set_up(system);
	REQUIRE(system.submit_frame(floor_frame()));
	REQUIRE(system.step(DT));
	const Vec3 good = system.forces().total;

	Frame bad = floor_frame();
	add_contact(bad, { NaN, 1.0, 0.0 });
	const Status status = system.submit_frame(bad);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "HapticFrame.contacts[1].normal"));
	CHECK(mentions(status, "not finite"));
	for (int k = 0; k < 10; ++k) {
		REQUIRE(system.step(DT));
	}
	CHECK(system.forces().total == good);
	CHECK(system.stats().frames_rejected == 1);
	CHECK(system.stats().frames_received == 1);
	CHECK(system.stats().non_finite_ticks == 0);
}

TEST_CASE("system: every bad parameter is named") {
	HapticsSystem system;
	set_up(system);
	struct Case {
		Status status;
		StatusCode code;
		const char *name;
	};
	Frame zero_normal;
	add_contact(zero_normal, {});
	Frame heavy;
	add_resting(heavy, { 0.0, -1.0, 0.0 }, -1.0);
	Frame fast;
	fast.velocity_m_per_s = { std::numeric_limits<double>::infinity(), 0.0, 0.0 };
	Frame soggy;
	set_water(soggy, true, NaN, 0.0);
	Frame stiff = floor_frame();
	stiff.contacts[0].material = ContactMaterial{ 1e9, 1.0 };
	ImpactEvent no_direction;
	no_direction.speed_m_per_s = 1.0;
	ImpactEvent nan_speed;
	nan_speed.direction = { 0.0, 1.0, 0.0 };
	nan_speed.speed_m_per_s = NaN;
	SafetyConfig slow_fade;
	slow_fade.watchdog_fade_s = 0.2;
	ForceModelConfig soft;
	soft.default_contact.stiffness_n = -1.0;
	const Case cases[] = {
		{ system.submit_frame(zero_normal), StatusCode::INVALID_ARGUMENT, "HapticFrame.contacts[0].normal" },
		{ system.submit_frame(heavy), StatusCode::OUT_OF_RANGE, "HapticFrame.resting[0].mass_kg" },
		{ system.submit_frame(fast), StatusCode::INVALID_ARGUMENT, "HapticFrame.velocity_m_per_s" },
		{ system.submit_frame(soggy), StatusCode::INVALID_ARGUMENT, "HapticFrame.water_drag_n_s_per_m" },
		{ system.submit_frame(stiff), StatusCode::OUT_OF_RANGE, "HapticFrame.contacts[0].material.stiffness_n" },
		{ system.push_impact(no_direction), StatusCode::INVALID_ARGUMENT, "HapticImpact.direction" },
		{ system.push_impact(nan_speed), StatusCode::INVALID_ARGUMENT, "HapticImpact.speed_m_per_s" },
		{ reconfigure(system, [&](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ true, NaN }; }), StatusCode::INVALID_ARGUMENT,
				"smoothing.cutoff_hz" },
		{ reconfigure(system, [&](RenderConfig &c) { c.servo.safety = slow_fade; }), StatusCode::OUT_OF_RANGE, "safety.watchdog_fade_s" },
		{ reconfigure(system, [&](RenderConfig &c) { c.movement.force_model = soft; }), StatusCode::OUT_OF_RANGE, "HapticMovementSettings.force_model.default_contact.stiffness_n" },
		{ reconfigure(system, [](RenderConfig &c) { c.servo.default_impact = ImpactMaterial{ 1.0, 5000.0, 0.01 }; }), StatusCode::OUT_OF_RANGE,
				"HapticServoSettings.default_impact.frequency_hz" },
		{ reconfigure(system, [](RenderConfig &c) { c.servo.input.input_radius_m = -1.0; }), StatusCode::OUT_OF_RANGE, "HapticServoSettings.input.input_radius_m" },
		{ reconfigure(system, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 0, true }; }), StatusCode::OUT_OF_RANGE, "telemetry.decimation" },
		{ system.set_hand_target({ 0.0, NaN, 0.0 }), StatusCode::INVALID_ARGUMENT, "hand_target" },
		{ system.start(100.0), StatusCode::OUT_OF_RANGE, "rate_hz" },
		{ system.start(NaN), StatusCode::INVALID_ARGUMENT, "rate_hz" },
		{ system.step(0.1), StatusCode::OUT_OF_RANGE, "dt" },
	};
	for (const Case &c : cases) {
		CAPTURE(c.name);
		CAPTURE(c.status.message());
		CHECK(c.status.code() == c.code);
		CHECK(mentions(c.status, c.name));
	}
	// Nothing rejected reached the configuration.
	const RenderConfig &config = system.config();
	CHECK_FALSE(config.movement.smoothing.enabled);
	CHECK(config.servo.safety.watchdog_fade_s == SafetyConfig{}.watchdog_fade_s);
	CHECK(config.movement.force_model.default_contact.stiffness_n == ContactMaterial{}.stiffness_n);
	CHECK(config.servo.input.input_radius_m == 0.0);
	CHECK_FALSE(system.is_running());
}

TEST_CASE("system: configuration changes take effect on the next tick") {
	HapticsSystem system;
	set_up(system);
	REQUIRE(system.submit_frame(floor_frame()));
	REQUIRE(system.step(DT));
	CHECK(system.forces().parts[NORMAL_FORCE].y == doctest::Approx(1.0));
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.movement.force_model.default_contact = ContactMaterial{ 4.0, 0.0 }; }));
	REQUIRE(system.step(DT));
	CHECK(system.forces().parts[NORMAL_FORCE].y == doctest::Approx(2.0));
	CHECK(system.forces().parts[FRICTION_FORCE] == Vec3{});
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.input.input_radius_m = 0.2; })); // Same position, half the input.
	REQUIRE(system.step(DT));
	CHECK(system.input_vector().y == doctest::Approx(-0.25));
	CHECK(system.forces().parts[NORMAL_FORCE].y == doctest::Approx(1.0));
}

TEST_CASE("system: telemetry has the documented layout") {
	HapticsSystem system;
	set_up(system);
	Frame frame = floor_frame();
	add_resting(frame, { 0.0, -1.0, 0.0 }, 0.5); // 0.5 N of crate (g = 1).
	set_water(frame, true, 0.5, 0.25);
	frame.velocity_m_per_s = { 1.0, 0.0, 0.0 };
	REQUIRE(system.submit_frame(frame));
	for (int k = 0; k < 3; ++k) {
		REQUIRE(system.step(DT));
	}
	std::vector<float> samples(10 * TELEMETRY_STRIDE, -1.0f);
	REQUIRE(system.drain_telemetry(samples.data(), 10) == 3);
	CHECK(system.drain_telemetry(samples.data(), 10) == 0);
	const float *s = samples.data() + 2 * TELEMETRY_STRIDE; // Third tick.
	CHECK(s[TELEMETRY_TIME] == doctest::Approx(0.003));
	CHECK(s[TELEMETRY_INPUT + 0] == doctest::Approx(0.3));
	CHECK(s[TELEMETRY_INPUT + 1] == doctest::Approx(-0.5));
	CHECK(s[TELEMETRY_POSITION + 0] == doctest::Approx(0.03));
	CHECK(s[TELEMETRY_POSITION + 1] == doctest::Approx(-0.05));
	CHECK(s[telemetry_part_column(NORMAL_FORCE) + 1] == doctest::Approx(1.0));
	CHECK(s[telemetry_part_column(FRICTION_FORCE) + 0] == doctest::Approx(-0.3));
	CHECK(s[telemetry_part_column(WEIGHT_FORCE) + 1] == doctest::Approx(-0.5));
	CHECK(s[telemetry_part_column(DRAG_FORCE) + 0] == doctest::Approx(-0.5));
	CHECK(s[telemetry_part_column(INERTIA_FORCE) + 1] == doctest::Approx(-0.25));
	CHECK(s[TELEMETRY_SMOOTHED + 0] == doctest::Approx(-0.8));
	CHECK(s[TELEMETRY_SMOOTHED + 1] == doctest::Approx(0.25));
	CHECK(s[TELEMETRY_IMPACT + 1] == 0.0f);
	CHECK(s[TELEMETRY_TOTAL + 0] == doctest::Approx(-0.8));
	CHECK(s[TELEMETRY_TOTAL + 1] == doctest::Approx(0.25));
	const auto flags = static_cast<uint32_t>(s[TELEMETRY_FLAGS]);
	CHECK(flags == (TELEMETRY_FLAG_CONTACT | TELEMETRY_FLAG_IN_WATER));
	const auto first_flags = static_cast<uint32_t>(samples[TELEMETRY_FLAGS]);
	CHECK((first_flags & TELEMETRY_FLAG_NEW_FRAME) != 0);
	CHECK(samples[3 * TELEMETRY_STRIDE] == -1.0f); // Nothing written past the count.
}

TEST_CASE("system: telemetry decimation, and overflow is counted") {
	HapticsSystem system;
	set_up(system);
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 5, true }; }));
	for (int k = 0; k < 100; ++k) {
		REQUIRE(system.step(DT));
	}
	std::vector<float> samples(TELEMETRY_QUEUE_CAPACITY * TELEMETRY_STRIDE);
	CHECK(system.drain_telemetry(samples.data(), TELEMETRY_QUEUE_CAPACITY) == 20);
	CHECK(samples[TELEMETRY_STRIDE + TELEMETRY_TIME] == doctest::Approx(0.006)); // Ticks 1, 6, 11...
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 1, true }; }));
	for (size_t k = 0; k < TELEMETRY_QUEUE_CAPACITY + 100; ++k) {
		REQUIRE(system.step(DT));
	}
	CHECK(system.stats().telemetry_drops == 100);
	CHECK(system.drain_telemetry(samples.data(), TELEMETRY_QUEUE_CAPACITY) == TELEMETRY_QUEUE_CAPACITY);
	CHECK(system.drain_telemetry(nullptr, 5) == 0);
}

TEST_CASE("system: impact overflow is counted, never fatal") {
	HapticsSystem system;
	set_up(system);
	ImpactEvent event;
	event.direction = { 0.0, 1.0, 0.0 };
	event.speed_m_per_s = 1.0;
	for (int n = 0; n < 100; ++n) {
		REQUIRE(system.push_impact(event)); // OK even when full.
	}
	CHECK(system.stats().transient_drops == 100 - IMPACT_QUEUE_CAPACITY);
	REQUIRE(system.step(DT)); // 64 arrive in a bank of 16.
	CHECK(system.stats().transient_drops == 100 - TransientBank::CAPACITY);
	CHECK(is_finite(system.forces().total));
	CHECK(length(system.forces().total) <= 3.3 + 1e-12);
}

TEST_CASE("system: manual stepping is exactly deterministic") {
	const auto script = [] {
		HapticsSystem system;
		REQUIRE(system.open_simulated_device()); // Spring-damper hand, default filter and safety.
		std::vector<float> telemetry(600 * TELEMETRY_STRIDE);
		for (int k = 0; k < 600; ++k) {
			if (k % 20 == 0) {
				Frame frame;
				add_contact(frame, { std::cos(k * 0.01), std::sin(k * 0.01), 0.0 });
				set_water(frame, k > 300, 0.4, 0.2);
				frame.velocity_m_per_s = { 0.5, -0.2, 0.0 };
				REQUIRE(system.submit_frame(frame));
				REQUIRE(system.set_hand_target({ 0.0008 * (k % 100), -0.03, 0.01 }));
			}
			if (k % 150 == 7) {
				ImpactEvent event;
				event.direction = { -1.0, 0.5, 0.0 };
				event.speed_m_per_s = 3.0;
				REQUIRE(system.push_impact(event));
			}
			REQUIRE(system.step(DT));
		}
		REQUIRE(system.drain_telemetry(telemetry.data(), 600) == 600);
		return telemetry;
	};
	const std::vector<float> a = script();
	const std::vector<float> b = script();
	CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

TEST_CASE("system: an unplugged device stops rendering with a clear error and keeps state") {
	HapticsSystem system;
	set_up(system);
	REQUIRE(system.submit_frame(floor_frame()));
	REQUIRE(system.step(DT));
	const Vec3 before = system.forces().total;
	const RenderConfig config_before = system.config();

	system.current_device()->software_cable()->set_plugged(false);
	const Status status = system.step(DT);
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(mentions(status, "disconnected"));
	CHECK(mentions(status, system.device_name()));
	CHECK(system.servo_status().code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(system.step(DT).code() == StatusCode::DEVICE_DISCONNECTED); // Still, not a crash.
	CHECK(system.has_device());
	CHECK(std::memcmp(&system.config(), &config_before, sizeof(RenderConfig)) == 0);
	CHECK(system.forces().total == before); // Last published output kept for the HUD.

	// Plugged back in and re-opened, the retained frame and configuration render again.
	system.current_device()->software_cable()->set_plugged(true);
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(system.open_simulated_device(device));
	REQUIRE(system.set_hand_target({ 0.03, -0.05, 0.0 }));
	CHECK(system.servo_status());
	REQUIRE(system.step(DT));
	CHECK(system.forces().total == before);
}

TEST_CASE("system: a device that fails to open leaves the current one in place") {
	HapticsSystem system;
	set_up(system);
	auto broken = std::make_unique<SimulatedDevice>();
	broken->set_plugged(false);
	const Status status = system.open_device(std::move(broken));
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(system.has_device());
	REQUIRE(system.submit_frame(floor_frame()));
	REQUIRE(system.step(DT));
	CHECK(system.forces().total.y == doctest::Approx(1.0));
	CHECK(system.open_device(nullptr).code() == StatusCode::INVALID_ARGUMENT);
}
