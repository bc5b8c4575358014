// The vehicle renderer on a wheel (renderers/vehicle/vehicle_renderer.h), in the system, stepped:
// on a scripted skid-pad the rim force has the model's sign and size, it follows the hand at
// every tick, it goes light as the front lets go, it fades out at standstill, a landing's load is
// capped, the damper brakes the wheel, and nothing is rendered before the game's first frame.

#include "vehicle_test_rig.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr double LOCK_RAD = 0.5;

double degrees(double p_degrees) {
	return p_degrees * std::numbers::pi / 180.0;
}

// One wheel at a known slip: F_z 4000 N, alpha 2 deg, grip 1, fast enough to be unfaded.
VehicleFrame one_wheel(double p_slip_rad, double p_steer_rad = 0.0) {
	VehicleFrame frame;
	frame.steer_angle_rad = p_steer_rad;
	frame.steer_lock_rad = LOCK_RAD;
	frame.steered_by_device = false;
	frame.reference_load_n = 4000.0;
	TyreContact contact;
	contact.in_contact = true;
	contact.load_n = 4000.0;
	contact.slip_angle_rad = p_slip_rad;
	contact.speed_m_per_s = 20.0;
	REQUIRE(frame.wheels.push_back(contact));
	return frame;
}

} // namespace

TEST_CASE("vehicle renderer: one tyre at 2 degrees gives the hand-worked rim force") {
	// M_kp = -62.51 N m (test_brush_tyre.cpp); the peak of one tyre at 4000 N is
	// 4000 x 0.021922 = 87.69 N m, felt as peak_force 2 N: the rim force is
	// -2 / 87.69 x -62.51 = +1.4257 N, to the right: the wheel is pulled back from the left turn.
	VehicleRig rig;
	rig.run(300, one_wheel(degrees(2.0)));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(1.4257).epsilon(0.002));
	CHECK(rig.wheel->written.x == doctest::Approx(1.4257).epsilon(0.002));
	const VehicleState state = rig.port().state();
	CHECK(state.aligning_torque_nm == doctest::Approx(-62.51).epsilon(0.001));
	CHECK(state.peak_torque_nm == doctest::Approx(87.69).epsilon(0.001));
	CHECK(state.lateral_force_n == doctest::Approx(1750.70).epsilon(0.001));
	CHECK(state.frames > 0);
}

TEST_CASE("vehicle renderer: on a skid-pad the rim force has the model's sign and size") {
	// R = 30 m at 12 m/s (0.49 g), turning left; the game steers with the wheel.
	const VehicleConfig config;
	for (const double steer_deg : { 4.0, 5.0, 6.0, 7.0 }) {
		CAPTURE(steer_deg);
		VehicleRig rig(config);
		const SkidPad pad;
		const double steer = degrees(steer_deg);
		const VehicleFrame frame = pad.frame(steer, 3300.0, 4700.0, LOCK_RAD);
		rig.wheel->angle = -steer / LOCK_RAD; // Turned left.
		rig.run(500, frame);
		const double expected = expected_rim_force(config, frame, steer);
		MESSAGE("skid-pad, road wheels at " << steer_deg << " deg: rim force " << rig.part(ALIGNING_FORCE)
											<< " N, model " << expected << " N, slips "
											<< frame.wheels[0].slip_angle_rad * 180.0 / std::numbers::pi << " / "
											<< frame.wheels[1].slip_angle_rad * 180.0 / std::numbers::pi << " deg");
		CHECK(expected > 0.2); // The wheel is pulled back to the right, toward straight ahead.
		CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected).epsilon(0.005));
		CHECK(rig.wheel->written.x == doctest::Approx(expected).epsilon(0.005));
		CHECK(rig.port().state().steer_angle_rad == doctest::Approx(steer));
	}
	// Turning right mirrors it.
	VehicleRig rig(config);
	SkidPad mirrored;
	mirrored.radius_m = -30.0; // Yaw rate negative: a right turn.
	const VehicleFrame frame = mirrored.frame(-degrees(5.0), 4700.0, 3300.0, LOCK_RAD);
	rig.wheel->angle = degrees(5.0) / LOCK_RAD;
	rig.run(500, frame);
	CHECK(rig.part(ALIGNING_FORCE) < -0.2);
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected_rim_force(config, frame, -degrees(5.0))).epsilon(0.005));
}

TEST_CASE("vehicle renderer: the torque follows the hand at every tick, between frames") {
	const VehicleConfig config;
	VehicleRig rig(config);
	const SkidPad pad;
	const double steer = degrees(5.0);
	const VehicleFrame frame = pad.frame(steer, 4000.0, 4000.0, LOCK_RAD);
	rig.wheel->angle = -steer / LOCK_RAD;
	rig.run(400, frame);
	// The hand turns one more degree in; no frame comes.
	const double further = degrees(6.0);
	rig.wheel->angle = -further / LOCK_RAD;
	REQUIRE(rig.system.step(VEHICLE_DT));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected_rim_force(config, frame, further)).epsilon(0.005));
	CHECK(rig.part(ALIGNING_FORCE) != doctest::Approx(expected_rim_force(config, frame, steer)).epsilon(0.005));
	// A game that steers by keys: the device's angle does not enter.
	VehicleFrame keys = frame;
	keys.steered_by_device = false;
	rig.run(400, keys);
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected_rim_force(config, keys, steer)).epsilon(0.005));
}

TEST_CASE("vehicle renderer: the steering goes light as the front lets go") {
	// Steering further into a fixed path: the rim force rises to the settings' peak_force
	// (2 N at the reference load) near lambda* = 0.46 (5.3 deg of slip), then falls to the
	// mechanical trail's share once the tyres slide.
	const VehicleConfig config;
	double best = 0.0;
	double best_slip = 0.0;
	double last = 0.0;
	bool flagged_past_peak = false;
	for (double slip_deg = 0.5; slip_deg <= 16.0; slip_deg += 0.5) {
		VehicleRig rig(config);
		VehicleFrame frame = one_wheel(degrees(slip_deg));
		rig.run(200, frame);
		const double force = rig.part(ALIGNING_FORCE);
		if (force > best) {
			best = force;
			best_slip = slip_deg;
		}
		if (slip_deg >= 12.0) {
			flagged_past_peak = flagged_past_peak || (rig.system.output().flags & TELEMETRY_FLAG_FRONT_LETTING_GO) != 0;
		}
		last = force;
	}
	MESSAGE("peak rim force " << best << " N at " << best_slip << " deg of slip; sliding: " << last << " N");
	CHECK(best == doctest::Approx(config.peak_force_n).epsilon(0.01));
	CHECK(best_slip == doctest::Approx(std::atan(0.464286 / 5.0) * 180.0 / std::numbers::pi).epsilon(0.1));
	// Sliding (lambda >= 1): t_m mu F_z = 80 N m, felt as 2 x 80 / 87.69 = 1.82 N.
	CHECK(last == doctest::Approx(2.0 * 80.0 / 87.69).epsilon(0.005));
	CHECK(flagged_past_peak);
}

TEST_CASE("vehicle renderer: standing still there is no aligning torque, it fades in with speed") {
	const VehicleConfig config; // low_speed_m_per_s 2
	VehicleRig rig(config);
	VehicleFrame frame = one_wheel(degrees(2.0));
	frame.wheels[0].speed_m_per_s = 0.0;
	rig.run(300, frame);
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(0.0));
	frame.wheels[0].speed_m_per_s = 1.0; // Half of low_speed.
	rig.run(500, frame);
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(1.4257 / 2.0).epsilon(0.005));
	CHECK(rig.port().state().speed_fade == doctest::Approx(0.5).epsilon(0.005));
	// A wheel in the air carries nothing.
	frame.wheels[0].speed_m_per_s = 20.0;
	frame.wheels[0].in_contact = false;
	rig.run(500, frame);
	CHECK(std::abs(rig.part(ALIGNING_FORCE)) < 1e-3);
}

TEST_CASE("vehicle renderer: a landing's load is capped at max_load_ratio times the reference load") {
	// One tyre at 2 degrees, reference load 4000 N, max_load_ratio 2: the model takes at most
	// 8000 N. The brush torque is proportional to the load at a fixed slip, so 8000 N gives
	// twice the 4000 N figures: M_kp = 2 x -62.51 = -125.02 N m, rim force 2 x 1.4257 = 2.8514 N.
	const VehicleConfig config; // max_load_ratio 2
	REQUIRE(config.max_load_ratio == 2.0);
	VehicleFrame landing = one_wheel(degrees(2.0));
	landing.wheels[0].load_n = 12000.0; // 3x standing: a landing after a hill.
	VehicleRig rig(config);
	rig.run(300, landing);
	const VehicleState capped = rig.port().state();
	MESSAGE("12000 N landing load (3x): torque " << capped.aligning_torque_nm << " N m, rim force "
												 << rig.part(ALIGNING_FORCE) << " N (uncapped: 4.2771 N)");
	CHECK(capped.aligning_torque_nm == doctest::Approx(-125.02).epsilon(0.001));
	CHECK(capped.lateral_force_n == doctest::Approx(2.0 * 1750.70).epsilon(0.001));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(2.8514).epsilon(0.002));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected_rim_force(config, landing, 0.0)).epsilon(0.001));

	// Below the cap a load is the model's as it is: 6000 N (1.5x) gives 1.5 x the 4000 N figures.
	VehicleFrame cornering = one_wheel(degrees(2.0));
	cornering.wheels[0].load_n = 6000.0;
	rig.run(300, cornering);
	MESSAGE("6000 N load (1.5x): torque " << rig.port().state().aligning_torque_nm << " N m, rim force "
										  << rig.part(ALIGNING_FORCE) << " N");
	CHECK(rig.port().state().aligning_torque_nm == doctest::Approx(-93.765).epsilon(0.001));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(2.1386).epsilon(0.002));

	// The setting moves the cap: at 3 the same landing is taken whole, 3 x 1.4257 = 4.2771 N.
	VehicleConfig loose = config;
	loose.max_load_ratio = 3.0;
	VehicleRig uncapped(loose);
	uncapped.run(300, landing);
	CHECK(uncapped.port().state().aligning_torque_nm == doctest::Approx(-187.53).epsilon(0.001));
	CHECK(uncapped.part(ALIGNING_FORCE) == doctest::Approx(4.2771).epsilon(0.002));
}

TEST_CASE("vehicle renderer: a landing's moment of 3x load pulls no harder than the cap") {
	// Rolling at 4000 N, the load jumps to 12000 N for three 60 Hz frames and back: the rim
	// force rises toward the capped 2.8514 N and no further, where uncapped it would near 4.28 N.
	VehicleRig rig;
	const VehicleFrame standing = one_wheel(degrees(2.0));
	VehicleFrame landing = standing;
	landing.wheels[0].load_n = 12000.0;
	rig.run(300, standing);
	double peak = 0.0;
	for (int t = 0; t < 48 + 200; ++t) {
		if (t % 16 == 0) {
			REQUIRE(rig.port().set_frame(t < 48 ? landing : standing));
		}
		REQUIRE(rig.system.step(VEHICLE_DT));
		peak = std::max(peak, rig.part(ALIGNING_FORCE));
	}
	MESSAGE("a 48 ms landing at 3x load: peak rim force " << peak << " N (capped 2.8514 N)");
	CHECK(peak > 2.5); // The cap's force is reached within the 48 ms (20 Hz filter).
	CHECK(peak <= 2.8514 * 1.002);
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(1.4257).epsilon(0.002)); // Back to standing.
}

TEST_CASE("vehicle renderer: the frame's steps are filtered, the first frame is taken as it is") {
	VehicleConfig config;
	config.input_filter_hz = 10.0;
	VehicleRig rig(config);
	rig.run(1, one_wheel(degrees(1.0)));
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(expected_rim_force(config, one_wheel(degrees(1.0)), 0.0)));
	// The slip grows by a fifth (small: the torque is nearly linear in it there): 16 ms later
	// (one 60 Hz frame) the force is 1 - e^(-2 pi 10 0.016) = 63 % of the way, not at once.
	const double before = rig.part(ALIGNING_FORCE);
	rig.run(16, one_wheel(degrees(1.2)), 100);
	const double target = expected_rim_force(config, one_wheel(degrees(1.2)), 0.0);
	const double share = (rig.part(ALIGNING_FORCE) - before) / (target - before);
	CHECK(share == doctest::Approx(1.0 - std::exp(-2.0 * std::numbers::pi * 10.0 * 0.016)).epsilon(0.03));
}

TEST_CASE("vehicle renderer: the damper brakes the wheel's motion") {
	VehicleConfig config;
	config.damping_n_s = 0.5;
	VehicleRig rig(config);
	VehicleFrame frame = one_wheel(0.0);
	frame.wheels[0].speed_m_per_s = 0.0;
	rig.run(100, frame);
	CHECK(rig.part(DAMPING_FORCE) == doctest::Approx(0.0));
	// Turned right at a full deflection a second for 0.2 s: -0.5 N once the estimate settles.
	for (int t = 0; t < 200; ++t) {
		rig.wheel->angle += VEHICLE_DT;
		REQUIRE(rig.system.step(VEHICLE_DT));
	}
	CHECK(rig.part(DAMPING_FORCE) == doctest::Approx(-0.5).epsilon(0.01));
	for (int t = 0; t < 200; ++t) {
		REQUIRE(rig.system.step(VEHICLE_DT));
	}
	CHECK(std::abs(rig.part(DAMPING_FORCE)) < 1e-3);
}

TEST_CASE("vehicle renderer: nothing before the game's first frame, and its frames feed the watchdog") {
	VehicleRig rig;
	rig.wheel->angle = -0.3;
	for (int t = 0; t < 200; ++t) {
		REQUIRE(rig.system.step(VEHICLE_DT));
	}
	CHECK(rig.wheel->written.x == 0.0);
	CHECK(rig.port().state().frames == 0);
	CHECK(rig.system.output().frame_age_s < 0.0); // No heartbeat yet.
	rig.run(600, one_wheel(degrees(2.0)));
	CHECK(rig.system.output().watchdog_gain == doctest::Approx(1.0));
	CHECK(rig.port().state().frames == doctest::Approx(600 / 16 + 1));
	// The game stops sending: the watchdog fades the force out.
	for (int t = 0; t < 300; ++t) {
		REQUIRE(rig.system.step(VEHICLE_DT));
	}
	CHECK(rig.system.output().watchdog_gain == 0.0);
	CHECK(rig.wheel->written.x == 0.0);
}
