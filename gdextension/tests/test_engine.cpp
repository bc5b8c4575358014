// The facade in manual-step mode: validation with named parameters and last-good-state,
// telemetry layout, determinism, drops, unplugging and device replacement.

#include "core/servo/telemetry.h"
#include "engine/haptics_engine.h"
#include "engine_config.h"
#include "renderers/movement/force_model.h"

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
void set_up(HapticsEngine &r_engine) {
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(r_engine.open_simulated_device(device));
	REQUIRE(r_engine.set_hand_target({ 0.03, -0.05, 0.0 }));
	REQUIRE(reconfigure(r_engine, [](RenderConfig &c) {
		c.movement.force_model = ForceModelConfig{};
		c.servo.input.dead_zone = 0.0;
	}));
	REQUIRE(reconfigure(r_engine, [](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ false, 13.0 }; }));
	SafetyConfig safety;
	safety.startup_ramp_s = 0.0;
	safety.slew_rate_n_per_s = 0.0;
	REQUIRE(reconfigure(r_engine, [&](RenderConfig &c) { c.servo.safety = safety; }));
}

Frame floor_frame() {
	Frame frame;
	frame.add_contact({ 0.0, 1.0, 0.0 });
	return frame;
}

} // namespace

TEST_CASE("engine: calls without a device fail cleanly") {
	HapticsEngine engine;
	CHECK(engine.step(DT).code() == StatusCode::NO_DEVICE);
	CHECK(engine.start().code() == StatusCode::NO_DEVICE);
	CHECK(engine.set_hand_target({}).code() == StatusCode::NO_DEVICE);
	CHECK(engine.calibrate().code() == StatusCode::NO_DEVICE);
	CHECK_FALSE(engine.is_running());
	CHECK(std::strcmp(engine.device_name(), "") == 0);
	CHECK(engine.submit_frame(floor_frame())); // Frames may arrive before a device.
	engine.stop();
	engine.close_device();
}

TEST_CASE("engine: manual step renders the hand-computed forces") {
	HapticsEngine engine;
	set_up(engine);
	REQUIRE(engine.submit_frame(floor_frame()));
	REQUIRE(engine.step(DT));
	const ForceComponents f = engine.forces();
	CHECK(engine.input_vector().x == doctest::Approx(0.3));
	CHECK(engine.input_vector().y == doctest::Approx(-0.5));
	CHECK(f.parts[NORMAL_FORCE].y == doctest::Approx(1.0));
	CHECK(f.parts[FRICTION_FORCE].x == doctest::Approx(-0.3));
	CHECK(f.total.x == doctest::Approx(-0.3));
	CHECK(f.total.y == doctest::Approx(1.0));
	const ServoStats stats = engine.stats();
	CHECK(stats.scheduler == SchedulerKind::MANUAL);
	CHECK(stats.ticks == 1);
	CHECK(stats.frames_received == 1);
	CHECK(stats.frame_age_s == 0.0);
}

TEST_CASE("engine: a NaN frame is rejected by name and the last good frame stays") {
	HapticsEngine engine;
	set_up(engine);
	REQUIRE(engine.submit_frame(floor_frame()));
	REQUIRE(engine.step(DT));
	const Vec3 good = engine.forces().total;

	Frame bad = floor_frame();
	bad.add_contact({ NaN, 1.0, 0.0 });
	const Status status = engine.submit_frame(bad);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "frame.contacts[1].normal"));
	CHECK(mentions(status, "not finite"));
	for (int k = 0; k < 10; ++k) {
		REQUIRE(engine.step(DT));
	}
	CHECK(engine.forces().total == good);
	CHECK(engine.stats().frames_rejected == 1);
	CHECK(engine.stats().frames_received == 1);
	CHECK(engine.stats().non_finite_ticks == 0);
}

TEST_CASE("engine: every bad parameter is named") {
	HapticsEngine engine;
	set_up(engine);
	struct Case {
		Status status;
		StatusCode code;
		const char *name;
	};
	Frame too_many;
	too_many.contact_count = MAX_CONTACTS + 1;
	Frame zero_normal;
	zero_normal.add_contact({});
	Frame heavy;
	heavy.add_resting({ 0.0, -1.0, 0.0 }, -1.0);
	Frame fast;
	fast.player_velocity = { std::numeric_limits<double>::infinity(), 0.0, 0.0 };
	Frame soggy;
	soggy.water = WaterState{ true, NaN, 0.0 };
	Frame stiff = floor_frame();
	stiff.contacts[0].use_default_material = false;
	stiff.contacts[0].material.stiffness = 1e9;
	ImpactEvent no_direction;
	no_direction.speed = 1.0;
	ImpactEvent nan_speed;
	nan_speed.direction = { 0.0, 1.0, 0.0 };
	nan_speed.speed = NaN;
	SafetyConfig slow_fade;
	slow_fade.watchdog_fade_s = 0.2;
	ForceModelConfig soft;
	soft.default_contact.stiffness = -1.0;
	const Case cases[] = {
		{ engine.submit_frame(too_many), StatusCode::OUT_OF_RANGE, "frame.contact_count" },
		{ engine.submit_frame(zero_normal), StatusCode::INVALID_ARGUMENT, "frame.contacts[0].normal" },
		{ engine.submit_frame(heavy), StatusCode::OUT_OF_RANGE, "frame.resting[0].mass" },
		{ engine.submit_frame(fast), StatusCode::INVALID_ARGUMENT, "frame.player_velocity" },
		{ engine.submit_frame(soggy), StatusCode::INVALID_ARGUMENT, "frame.water.drag" },
		{ engine.submit_frame(stiff), StatusCode::OUT_OF_RANGE, "frame.contacts[0].material.stiffness" },
		{ engine.push_impact(no_direction), StatusCode::INVALID_ARGUMENT, "impact.direction" },
		{ engine.push_impact(nan_speed), StatusCode::INVALID_ARGUMENT, "impact.speed" },
		{ reconfigure(engine, [&](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ true, NaN }; }), StatusCode::INVALID_ARGUMENT,
				"smoothing.cutoff_hz" },
		{ reconfigure(engine, [&](RenderConfig &c) { c.servo.safety = slow_fade; }), StatusCode::OUT_OF_RANGE, "safety.watchdog_fade_s" },
		{ reconfigure(engine, [&](RenderConfig &c) { c.movement.force_model = soft; }), StatusCode::OUT_OF_RANGE, "force_model.contact_stiffness_n" },
		{ reconfigure(engine, [](RenderConfig &c) { c.servo.default_impact = ImpactMaterial{ 1.0, 5000.0, 0.01 }; }), StatusCode::OUT_OF_RANGE,
				"force_model.impact_frequency_hz" },
		{ reconfigure(engine, [](RenderConfig &c) { c.servo.input.input_radius_m = -1.0; }), StatusCode::OUT_OF_RANGE, "force_model.input_radius_m" },
		{ reconfigure(engine, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 0, true }; }), StatusCode::OUT_OF_RANGE, "telemetry.decimation" },
		{ engine.set_hand_target({ 0.0, NaN, 0.0 }), StatusCode::INVALID_ARGUMENT, "hand_target" },
		{ engine.start(100.0), StatusCode::OUT_OF_RANGE, "rate_hz" },
		{ engine.start(NaN), StatusCode::INVALID_ARGUMENT, "rate_hz" },
		{ engine.step(0.1), StatusCode::OUT_OF_RANGE, "dt" },
	};
	for (const Case &c : cases) {
		CAPTURE(c.name);
		CAPTURE(c.status.message());
		CHECK(c.status.code() == c.code);
		CHECK(mentions(c.status, c.name));
	}
	// Nothing rejected reached the configuration.
	const RenderConfig &config = engine.config();
	CHECK_FALSE(config.movement.smoothing.enabled);
	CHECK(config.servo.safety.watchdog_fade_s == SafetyConfig{}.watchdog_fade_s);
	CHECK(config.movement.force_model.default_contact.stiffness == ContactMaterial{}.stiffness);
	CHECK(config.servo.input.input_radius_m == 0.0);
	CHECK_FALSE(engine.is_running());
}

TEST_CASE("engine: configuration changes take effect on the next tick") {
	HapticsEngine engine;
	set_up(engine);
	REQUIRE(engine.submit_frame(floor_frame()));
	REQUIRE(engine.step(DT));
	CHECK(engine.forces().parts[NORMAL_FORCE].y == doctest::Approx(1.0));
	REQUIRE(reconfigure(engine, [](RenderConfig &c) { c.movement.force_model.default_contact = ContactMaterial{ 4.0, 0.0 }; }));
	REQUIRE(engine.step(DT));
	CHECK(engine.forces().parts[NORMAL_FORCE].y == doctest::Approx(2.0));
	CHECK(engine.forces().parts[FRICTION_FORCE] == Vec3{});
	REQUIRE(reconfigure(engine, [](RenderConfig &c) { c.servo.input.input_radius_m = 0.2; })); // Same position, half the input.
	REQUIRE(engine.step(DT));
	CHECK(engine.input_vector().y == doctest::Approx(-0.25));
	CHECK(engine.forces().parts[NORMAL_FORCE].y == doctest::Approx(1.0));
}

TEST_CASE("engine: telemetry has the documented layout") {
	HapticsEngine engine;
	set_up(engine);
	Frame frame = floor_frame();
	frame.add_resting({ 0.0, -1.0, 0.0 }, 0.5); // 0.5 N of crate (g = 1).
	frame.water = WaterState{ true, 0.5, 0.25 };
	frame.player_velocity = { 1.0, 0.0, 0.0 };
	REQUIRE(engine.submit_frame(frame));
	for (int k = 0; k < 3; ++k) {
		REQUIRE(engine.step(DT));
	}
	std::vector<float> samples(10 * TELEMETRY_STRIDE, -1.0f);
	REQUIRE(engine.drain_telemetry(samples.data(), 10) == 3);
	CHECK(engine.drain_telemetry(samples.data(), 10) == 0);
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

TEST_CASE("engine: telemetry decimation, and overflow is counted") {
	HapticsEngine engine;
	set_up(engine);
	REQUIRE(reconfigure(engine, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 5, true }; }));
	for (int k = 0; k < 100; ++k) {
		REQUIRE(engine.step(DT));
	}
	std::vector<float> samples(TELEMETRY_QUEUE_CAPACITY * TELEMETRY_STRIDE);
	CHECK(engine.drain_telemetry(samples.data(), TELEMETRY_QUEUE_CAPACITY) == 20);
	CHECK(samples[TELEMETRY_STRIDE + TELEMETRY_TIME] == doctest::Approx(0.006)); // Ticks 1, 6, 11...
	REQUIRE(reconfigure(engine, [](RenderConfig &c) { c.servo.telemetry = TelemetryConfig{ 1, true }; }));
	for (size_t k = 0; k < TELEMETRY_QUEUE_CAPACITY + 100; ++k) {
		REQUIRE(engine.step(DT));
	}
	CHECK(engine.stats().telemetry_drops == 100);
	CHECK(engine.drain_telemetry(samples.data(), TELEMETRY_QUEUE_CAPACITY) == TELEMETRY_QUEUE_CAPACITY);
	CHECK(engine.drain_telemetry(nullptr, 5) == 0);
}

TEST_CASE("engine: impact overflow is counted, never fatal") {
	HapticsEngine engine;
	set_up(engine);
	ImpactEvent event;
	event.direction = { 0.0, 1.0, 0.0 };
	event.speed = 1.0;
	for (int n = 0; n < 100; ++n) {
		REQUIRE(engine.push_impact(event)); // OK even when full.
	}
	CHECK(engine.stats().transient_drops == 100 - IMPACT_QUEUE_CAPACITY);
	REQUIRE(engine.step(DT)); // 64 arrive in a bank of 16.
	CHECK(engine.stats().transient_drops == 100 - TransientBank::CAPACITY);
	CHECK(is_finite(engine.forces().total));
	CHECK(length(engine.forces().total) <= 3.3 + 1e-12);
}

TEST_CASE("engine: manual stepping is exactly deterministic") {
	const auto script = [] {
		HapticsEngine engine;
		REQUIRE(engine.open_simulated_device()); // Spring-damper hand, default filter and safety.
		std::vector<float> telemetry(600 * TELEMETRY_STRIDE);
		for (int k = 0; k < 600; ++k) {
			if (k % 20 == 0) {
				Frame frame;
				frame.add_contact({ std::cos(k * 0.01), std::sin(k * 0.01), 0.0 });
				frame.water = WaterState{ k > 300, 0.4, 0.2 };
				frame.player_velocity = { 0.5, -0.2, 0.0 };
				REQUIRE(engine.submit_frame(frame));
				REQUIRE(engine.set_hand_target({ 0.0008 * (k % 100), -0.03, 0.01 }));
			}
			if (k % 150 == 7) {
				ImpactEvent event;
				event.direction = { -1.0, 0.5, 0.0 };
				event.speed = 3.0;
				REQUIRE(engine.push_impact(event));
			}
			REQUIRE(engine.step(DT));
		}
		REQUIRE(engine.drain_telemetry(telemetry.data(), 600) == 600);
		return telemetry;
	};
	const std::vector<float> a = script();
	const std::vector<float> b = script();
	CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

TEST_CASE("engine: an unplugged device stops rendering with a clear error and keeps state") {
	HapticsEngine engine;
	set_up(engine);
	REQUIRE(engine.submit_frame(floor_frame()));
	REQUIRE(engine.step(DT));
	const Vec3 before = engine.forces().total;
	const RenderConfig config_before = engine.config();

	engine.current_device()->software_cable()->set_plugged(false);
	const Status status = engine.step(DT);
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(mentions(status, "disconnected"));
	CHECK(mentions(status, engine.device_name()));
	CHECK(engine.servo_status().code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(engine.step(DT).code() == StatusCode::DEVICE_DISCONNECTED); // Still, not a crash.
	CHECK(engine.has_device());
	CHECK(std::memcmp(&engine.config(), &config_before, sizeof(RenderConfig)) == 0);
	CHECK(engine.forces().total == before); // Last published output kept for the HUD.

	// Plugged back in and re-opened, the retained frame and configuration render again.
	engine.current_device()->software_cable()->set_plugged(true);
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(engine.open_simulated_device(device));
	REQUIRE(engine.set_hand_target({ 0.03, -0.05, 0.0 }));
	CHECK(engine.servo_status());
	REQUIRE(engine.step(DT));
	CHECK(engine.forces().total == before);
}

TEST_CASE("engine: a device that fails to open leaves the current one in place") {
	HapticsEngine engine;
	set_up(engine);
	auto broken = std::make_unique<SimulatedDevice>();
	broken->set_plugged(false);
	const Status status = engine.open_device(std::move(broken));
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(engine.has_device());
	REQUIRE(engine.submit_frame(floor_frame()));
	REQUIRE(engine.step(DT));
	CHECK(engine.forces().total.y == doctest::Approx(1.0));
	CHECK(engine.open_device(nullptr).code() == StatusCode::INVALID_ARGUMENT);
}
