// The vehicle renderer's road and its limits, on a wheel in the system (vehicle_test_rig.h): a
// kerb's ripple at speed / spacing Hz with its amplitude, a rough surface's noise at its RMS, a
// crash's impact transient on top of the steering, a refused frame that changes nothing, and a
// force that stays finite and within the wheel's limits whatever the frames say.

#include "core/wire/codec.h"
#include "vehicle_test_rig.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

// Rolling straight (no torque) at p_speed over a surface.
VehicleFrame rolling(double p_speed_m_per_s, double p_ripple_n, double p_spacing_m, double p_roughness_n) {
	VehicleFrame frame;
	frame.steered_by_device = false;
	frame.reference_load_n = 4000.0;
	for (int w = 0; w < 2; ++w) {
		TyreContact contact;
		contact.in_contact = true;
		contact.load_n = 4000.0;
		contact.speed_m_per_s = p_speed_m_per_s;
		// A kerb under the left wheel only.
		contact.ripple_n = w == 0 ? p_ripple_n : 0.0;
		contact.ripple_spacing_m = w == 0 ? p_spacing_m : 0.0;
		contact.roughness_n = p_roughness_n;
		REQUIRE(frame.wheels.push_back(contact));
	}
	return frame;
}

// Upward zero crossings of p_samples.
int rising_crossings(const std::vector<double> &p_samples) {
	int count = 0;
	for (size_t i = 1; i < p_samples.size(); ++i) {
		count += (p_samples[i - 1] < 0.0 && p_samples[i] >= 0.0) ? 1 : 0;
	}
	return count;
}

} // namespace

TEST_CASE("vehicle road: a kerb ripples at speed / spacing with its amplitude, at the rim") {
	// 10 m/s over ridges 0.25 m apart: 40 Hz, 0.8 N.
	VehicleRig rig;
	const VehicleFrame frame = rolling(10.0, 0.8, 0.25, 0.0);
	std::vector<double> texture;
	std::vector<double> written;
	for (int t = 0; t < 1000; ++t) {
		if (t % 16 == 0) {
			REQUIRE(rig.port().set_frame(frame));
		}
		REQUIRE(rig.system.step(VEHICLE_DT));
		texture.push_back(rig.part(TEXTURE_FORCE));
		written.push_back(rig.wheel->written.x);
	}
	const int cycles = rising_crossings(texture);
	const double peak = *std::max_element(texture.begin(), texture.end());
	MESSAGE("kerb at 10 m/s, 0.25 m: " << cycles << " cycles in 1 s, peak " << peak << " N");
	CHECK(cycles >= 39);
	CHECK(cycles <= 41);
	CHECK(peak == doctest::Approx(0.8).epsilon(0.02));
	CHECK(*std::min_element(texture.begin(), texture.end()) == doctest::Approx(-0.8).epsilon(0.02));
	CHECK(rising_crossings(written) == cycles); // The wheel gets it (no torque rolling straight).
	CHECK(rig.port().state().ripple_hz == doctest::Approx(40.0));
	CHECK((rig.system.output().flags & TELEMETRY_FLAG_RIPPLE) != 0);

	// Twice the speed, twice the frequency; off the kerb, none.
	texture.clear();
	const VehicleFrame faster = rolling(20.0, 0.8, 0.25, 0.0);
	for (int t = 0; t < 1000; ++t) {
		if (t % 16 == 0) {
			REQUIRE(rig.port().set_frame(faster));
		}
		REQUIRE(rig.system.step(VEHICLE_DT));
		texture.push_back(rig.part(TEXTURE_FORCE));
	}
	CHECK(rising_crossings(texture) >= 79);
	CHECK(rising_crossings(texture) <= 81);
	rig.run(100, rolling(20.0, 0.0, 0.0, 0.0));
	CHECK(rig.part(TEXTURE_FORCE) == 0.0);
	CHECK((rig.system.output().flags & TELEMETRY_FLAG_RIPPLE) == 0);
}

TEST_CASE("vehicle road: rolling onto a kerb starts the ripple without a step") {
	VehicleRig rig;
	rig.run(100, rolling(10.0, 0.0, 0.0, 0.0));
	REQUIRE(rig.port().set_frame(rolling(10.0, 2.0, 0.25, 0.0)));
	REQUIRE(rig.system.step(VEHICLE_DT));
	// The first sample is sin(2 pi 40 x 0.001) x 2 N = 0.50 N, not up to 2 N.
	CHECK(rig.part(TEXTURE_FORCE) == doctest::Approx(2.0 * std::sin(2.0 * std::numbers::pi * 0.04)).epsilon(1e-6));
}

TEST_CASE("vehicle road: roughness has its RMS at speed, less slower, none standing") {
	VehicleRig rig; // roughness_speed_m_per_s 5
	for (const double speed : { 10.0, 2.5 }) {
		CAPTURE(speed);
		const VehicleFrame frame = rolling(speed, 0.0, 0.0, 0.3);
		rig.run(200, frame);
		double sum_sq = 0.0;
		double largest = 0.0;
		for (int t = 0; t < 4000; ++t) {
			if (t % 16 == 0) {
				REQUIRE(rig.port().set_frame(frame));
			}
			REQUIRE(rig.system.step(VEHICLE_DT));
			const double x = rig.part(TEXTURE_FORCE);
			sum_sq += x * x;
			largest = std::max(largest, std::abs(x));
		}
		// Two wheels of independent noise, each 0.3 N x min(1, v / 5) RMS: sqrt(2) of it.
		const double expected = std::sqrt(2.0) * 0.3 * std::min(1.0, speed / 5.0);
		const double rms = std::sqrt(sum_sq / 4000.0);
		MESSAGE("roughness 0.3 N at " << speed << " m/s: RMS " << rms << " N (expected " << expected << "), largest "
									  << largest << " N");
		CHECK(rms == doctest::Approx(expected).epsilon(0.25));
		CHECK(largest <= 2.0 * 3.0 * 0.3 * std::min(1.0, speed / 5.0) + 1e-9);
	}
	rig.run(200, rolling(0.0, 0.0, 0.0, 0.3));
	CHECK(rig.part(TEXTURE_FORCE) == 0.0);
}

TEST_CASE("vehicle road: a crash's impact rings on the wheel over the steering, sized by its speed") {
	// The game's impact: 3 m/s of change of velocity, 0.5 N per m/s, pushed along (1, 0, 1)/sqrt 2
	// (a wheel feels the x of it): A = 1.5 N, 1.06 N on the wheel's axis.
	VehicleRig rig;
	const VehicleFrame frame = rolling(10.0, 0.0, 0.0, 0.0);
	rig.run(200, frame);
	CHECK(rig.wheel->written.x == doctest::Approx(0.0));
	ImpactEvent crash;
	crash.direction = Vec3(1.0, 0.0, 1.0);
	crash.speed_m_per_s = 3.0;
	crash.material = ImpactMaterial{ 0.5, 100.0, 0.03 };
	REQUIRE(rig.system.push_impact(crash));
	double peak = 0.0;
	double expected_peak = 0.0;
	for (int t = 1; t <= 100; ++t) {
		REQUIRE(rig.system.step(VEHICLE_DT));
		peak = std::max(peak, rig.wheel->written.x);
		const double time = t * VEHICLE_DT;
		expected_peak = std::max(expected_peak,
				1.5 / std::sqrt(2.0) * std::exp(-time / 0.03) * std::sin(2.0 * std::numbers::pi * 100.0 * time));
	}
	MESSAGE("crash of 3 m/s: peak " << peak << " N on the wheel (expected " << expected_peak << " N)");
	CHECK(peak == doctest::Approx(expected_peak).epsilon(0.01));
	CHECK(peak > 0.9);
}

TEST_CASE("vehicle road: a frame with NaN or out of range is refused by name and the renderer goes on") {
	VehicleRig rig;
	VehicleFrame frame = rolling(10.0, 0.0, 0.0, 0.0);
	frame.wheels[0].slip_angle_rad = 0.05;
	frame.steer_angle_rad = 0.05;
	rig.run(300, frame);
	const double before = rig.part(ALIGNING_FORCE);
	const uint64_t frames = rig.port().state().frames;
	REQUIRE(before != 0.0);

	VehicleFrame bad = frame;
	bad.wheels[1].load_n = std::numeric_limits<double>::quiet_NaN();
	const Status nan = rig.port().set_frame(bad);
	CHECK_FALSE(nan);
	CHECK(std::string(nan.message()).find("wheels[1].load_n") != std::string::npos);
	CHECK(std::string(nan.message()).find("not finite") != std::string::npos);
	bad = frame;
	bad.wheels[0].slip_angle_rad = 2.0;
	const Status range = rig.port().set_frame(bad);
	CHECK_FALSE(range);
	CHECK(std::string(range.message()).find("wheels[0].slip_angle_rad: 2 is outside [-1.5, 1.5]") != std::string::npos);
	// As bytes, the way GDScript sends it.
	bad = frame;
	bad.steer_lock_rad = 0.0;
	const Status bytes = rig.port().receive(encode(bad));
	CHECK_FALSE(bytes);
	CHECK(std::string(bytes.message()).find("steer_lock_rad") != std::string::npos);
	CHECK_FALSE(rig.port().receive(encode(VehicleState{})));

	for (int t = 0; t < 50; ++t) {
		REQUIRE(rig.system.step(VEHICLE_DT));
	}
	CHECK(rig.part(ALIGNING_FORCE) == doctest::Approx(before)); // Still the last good frame's.
	CHECK(rig.port().state().frames == frames);
	CHECK(std::isfinite(rig.wheel->written.x));
}

TEST_CASE("vehicle road: whatever the frames and the hand, the force is finite and within the wheel's limits") {
	VehicleConfig config;
	config.peak_force_n = 100.0;
	config.damping_n_s = 10.0;
	VehicleRig rig(config);
	std::mt19937 random(38);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	double largest = 0.0;
	int ticks = 0;
	for (int frame_index = 0; frame_index < 400; ++frame_index) {
		VehicleFrame frame;
		frame.steer_angle_rad = (unit(random) * 2.0 - 1.0) * MAX_STEER_ANGLE_RAD;
		frame.steer_lock_rad = 0.01 + unit(random) * (MAX_STEER_ANGLE_RAD - 0.01);
		frame.steered_by_device = unit(random) < 0.5;
		frame.reference_load_n = frame_index % 7 == 0 ? 0.001 : unit(random) * MAX_TYRE_LOAD_N;
		const int wheels = static_cast<int>(unit(random) * (VEHICLE_MAX_STEERED_WHEELS + 1));
		for (int w = 0; w < std::min<int>(wheels, VEHICLE_MAX_STEERED_WHEELS); ++w) {
			TyreContact contact;
			contact.in_contact = unit(random) < 0.8;
			contact.load_n = unit(random) * MAX_TYRE_LOAD_N;
			contact.slip_angle_rad = (unit(random) * 2.0 - 1.0) * MAX_SLIP_ANGLE_RAD;
			contact.rolling_backward = unit(random) < 0.3;
			contact.speed_m_per_s = unit(random) * MAX_SPEED_M_PER_S;
			contact.grip = unit(random) * MAX_GRIP;
			contact.roughness_n = unit(random) * MAX_TEXTURE_N;
			contact.ripple_n = unit(random) * MAX_TEXTURE_N;
			contact.ripple_spacing_m = unit(random) < 0.5 ? 0.0 : 0.01 + unit(random) * 5.0;
			REQUIRE(frame.wheels.push_back(contact));
		}
		REQUIRE(rig.port().set_frame(frame));
		for (int t = 0; t < 17; ++t) {
			rig.wheel->angle = std::clamp(rig.wheel->angle + (unit(random) - 0.5) * 0.4, -1.0, 1.0);
			REQUIRE(rig.system.step(VEHICLE_DT));
			const ForceComponents forces = rig.system.forces();
			for (const Vec3 &part : forces.parts) {
				REQUIRE(std::isfinite(part.x));
			}
			REQUIRE(std::isfinite(rig.wheel->written.x));
			REQUIRE(std::abs(rig.wheel->written.x) <= TestWheel::MAX_FORCE_N + 1e-9);
			REQUIRE(std::abs(forces.smoothed.x) <= TestWheel::MAX_CONTINUOUS_N + 1e-9);
			largest = std::max(largest, std::abs(rig.wheel->written.x));
			++ticks;
		}
	}
	MESSAGE(ticks << " ticks of random frames: largest force " << largest << " N");
	CHECK(rig.system.output().non_finite_ticks == 0);
	CHECK(largest > 2.0); // The frames did ask for far more than the wheel may give.
}
