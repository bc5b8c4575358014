// Stamper delta kinematics with docs/devices/falcon.md's constants: encoder angles, IK/FK round trips over
// the workspace, the Jacobian against finite differences, force -> motor words (J^T F, the
// |torque| > 30 scaling, x10000, negation, int16), and unreachable input as errors.

#include "devices/falcon/falcon_axes.h"
#include "devices/falcon/falcon_kinematics.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <numbers>

using namespace haptics;
using namespace haptics::falcon;

namespace {

Vec3 theta1_of(const Vec3 &p_position) {
	FalconAngles angles;
	REQUIRE(falcon_inverse_kinematics(p_position, angles));
	return { angles.leg[0].theta1, angles.leg[1].theta1, angles.leg[2].theta1 };
}

} // namespace

TEST_CASE("falcon kinematics: encoder -> angle vectors") {
	CHECK(encoder_to_theta_deg(0) == doctest::Approx(35.0).epsilon(1e-12));
	CHECK(encoder_to_theta_deg(1000) == doctest::Approx(71.43466).epsilon(1e-7));
	CHECK(encoder_to_theta_deg(-1447) == doctest::Approx(-17.72095).epsilon(1e-6));
	CHECK(FALCON_DEG_PER_COUNT == doctest::Approx(0.0364347).epsilon(1e-6));
	CHECK(encoder_to_theta_rad(0) == doctest::Approx(35.0 * std::numbers::pi / 180.0));
	// And back, to the nearest count, clamped to int16.
	CHECK(theta_rad_to_encoder(encoder_to_theta_rad(1000)) == 1000);
	CHECK(theta_rad_to_encoder(encoder_to_theta_rad(-1447)) == -1447);
	CHECK(theta_rad_to_encoder(1e9) == INT16_MAX);
	CHECK(theta_rad_to_encoder(-1e9) == INT16_MIN);
	CHECK(theta_rad_to_encoder(std::numeric_limits<double>::quiet_NaN()) == INT16_MIN);
}

TEST_CASE("falcon kinematics: on the z axis all three legs share one angle") {
	const Vec3 theta = theta1_of({ 0.0, 0.0, 0.125 });
	CHECK(theta.x == doctest::Approx(theta.y).epsilon(1e-12));
	CHECK(theta.x == doctest::Approx(theta.z).epsilon(1e-12));
	// Pulling the grip out (z up) raises the thighs.
	const Vec3 out = theta1_of({ 0.0, 0.0, 0.150 });
	CHECK(out.x > theta.x);
}

TEST_CASE("falcon kinematics: FK(IK(p)) == p within 1e-6 m over a grid spanning the workspace") {
	int points = 0;
	double worst = 0.0;
	for (double x = -0.05; x <= 0.0501; x += 0.01) {
		for (double y = -0.05; y <= 0.0501; y += 0.01) {
			for (double z = -0.05; z <= 0.0501; z += 0.01) {
				const Vec3 offset{ x, y, z };
				if (length(offset) > 0.0501) {
					continue; // The 0.05 m sphere around the centre.
				}
				const Vec3 p = FALCON_KINEMATIC_CENTRE + offset;
				FalconAngles angles;
				REQUIRE(falcon_inverse_kinematics(p, angles));
				const double theta[3] = { angles.leg[0].theta1, angles.leg[1].theta1, angles.leg[2].theta1 };
				Vec3 recovered;
				// Cold start from the centre, the hardest case.
				const Status status = falcon_forward_kinematics(theta, FALCON_KINEMATIC_CENTRE, recovered);
				REQUIRE_MESSAGE(status, status.message());
				worst = std::fmax(worst, length(recovered - p));
				++points;
			}
		}
	}
	MESSAGE("FK(IK(p)) over " << points << " points: worst error " << worst << " m");
	CHECK(points > 400);
	CHECK(worst < 1e-6);
}

TEST_CASE("falcon kinematics: FK from encoder counts lands within one count's resolution") {
	const Vec3 p{ 0.012, -0.021, 0.131 };
	const Vec3 theta = theta1_of(p);
	const double quantised[3] = { encoder_to_theta_rad(theta_rad_to_encoder(theta.x)),
		encoder_to_theta_rad(theta_rad_to_encoder(theta.y)), encoder_to_theta_rad(theta_rad_to_encoder(theta.z)) };
	Vec3 recovered;
	int32_t iterations = 0;
	REQUIRE(falcon_forward_kinematics(quantised, p, recovered, &iterations));
	CHECK(length(recovered - p) < 2e-4); // ~0.06 mm per count per leg.
	CHECK(iterations <= 4); // Warm start.
}

TEST_CASE("falcon kinematics: the Jacobian matches finite differences of the IK") {
	const Vec3 points[] = { { 0.0, 0.0, 0.125 }, { 0.03, -0.02, 0.11 }, { -0.035, 0.03, 0.15 }, { 0.0, 0.04, 0.10 } };
	for (const Vec3 &p : points) {
		CAPTURE(p.x);
		CAPTURE(p.y);
		CAPTURE(p.z);
		FalconAngles angles;
		REQUIRE(falcon_inverse_kinematics(p, angles));
		Mat3 jacobian;
		REQUIRE(falcon_angle_jacobian(angles, jacobian));
		const double h = 1e-7;
		const Vec3 axes[3] = { { h, 0, 0 }, { 0, h, 0 }, { 0, 0, h } };
		for (int column = 0; column < 3; ++column) {
			const Vec3 derivative = (theta1_of(p + axes[column]) - theta1_of(p - axes[column])) / (2.0 * h);
			const double expected[3] = { derivative.x, derivative.y, derivative.z };
			for (int row = 0; row < 3; ++row) {
				CHECK(jacobian.m[row][column] == doctest::Approx(expected[row]).epsilon(1e-6).scale(1.0));
			}
		}
		// And dp/dtheta is its inverse.
		Mat3 dp_dtheta;
		REQUIRE(falcon_position_jacobian(p, dp_dtheta));
		const Vec3 v{ 0.1, -0.2, 0.3 };
		const Vec3 round_trip = dp_dtheta * (jacobian * v);
		CHECK(length(round_trip - v) < 1e-9);
	}
}

TEST_CASE("falcon kinematics: unreachable points and bad input are errors, never NaN") {
	FalconAngles angles;
	Status status = falcon_inverse_kinematics({ 0.0, 0.0, 0.5 }, angles);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::strstr(status.message(), "unreachable") != nullptr);
	CHECK(falcon_inverse_kinematics({ 0.3, 0.0, 0.125 }, angles).code() == StatusCode::OUT_OF_RANGE);
	CHECK(falcon_inverse_kinematics({ 0.0, 0.0, 0.0 }, angles).code() == StatusCode::OUT_OF_RANGE);
	const double nan = std::numeric_limits<double>::quiet_NaN();
	CHECK(falcon_inverse_kinematics({ nan, 0.0, 0.1 }, angles).code() == StatusCode::INVALID_ARGUMENT);

	Vec3 position{ 1.0, 2.0, 3.0 };
	const double wild[3] = { 3.0, -3.0, 3.0 }; // Radians no configuration reaches.
	status = falcon_forward_kinematics(wild, FALCON_KINEMATIC_CENTRE, position);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::strstr(status.message(), "no position") != nullptr);
	CHECK(position == Vec3{ 1.0, 2.0, 3.0 }); // Untouched.
	const double nans[3] = { nan, 0.0, 0.0 };
	CHECK(falcon_forward_kinematics(nans, FALCON_KINEMATIC_CENTRE, position).code() == StatusCode::INVALID_ARGUMENT);
	// Extreme encoder counts either give a finite position or an error.
	for (int32_t count : { -32768, -20000, -5000, 5000, 20000, 32767 }) {
		const double theta[3] = { encoder_to_theta_rad(count), encoder_to_theta_rad(0), encoder_to_theta_rad(-count) };
		Vec3 p;
		if (falcon_forward_kinematics(theta, FALCON_KINEMATIC_CENTRE, p)) {
			CHECK(is_finite(p));
		}
	}

	MotorWords words;
	words.word[0] = 7;
	CHECK(falcon_force_to_motor_words(FALCON_KINEMATIC_CENTRE, { nan, 0, 0 }, words).code() == StatusCode::INVALID_ARGUMENT);
	CHECK(falcon_force_to_motor_words({ 0.0, 0.0, 0.5 }, { 1, 0, 0 }, words).code() == StatusCode::OUT_OF_RANGE);
	CHECK(words.word[0] == 7); // Untouched on error.
}

TEST_CASE("falcon kinematics: force -> motor words is -10000 J^T F, and the inverse recovers F") {
	const Vec3 p{ 0.01, 0.02, 0.12 };
	const Vec3 force{ 1.5, -2.0, 3.0 };
	Mat3 dp_dtheta;
	REQUIRE(falcon_position_jacobian(p, dp_dtheta));
	const Vec3 torque = dp_dtheta.transposed() * force;
	MotorWords words;
	REQUIRE(falcon_force_to_motor_words(p, force, words));
	CHECK_FALSE(words.torque_limited);
	CHECK_FALSE(words.word_limited);
	CHECK(words.word[0] == std::lround(-10000.0 * torque.x));
	CHECK(words.word[1] == std::lround(-10000.0 * torque.y));
	CHECK(words.word[2] == std::lround(-10000.0 * torque.z));
	Vec3 back;
	REQUIRE(falcon_motor_words_to_force(p, words.word, back));
	CHECK(length(back - force) < 1e-3); // Rounding to whole words.
	// Zero force, zero words.
	REQUIRE(falcon_force_to_motor_words(p, Vec3{}, words));
	CHECK(words.word[0] == 0);
	CHECK(words.word[1] == 0);
	CHECK(words.word[2] == 0);
}

TEST_CASE("falcon kinematics: pushing the grip up (+y) needs torques, and the sign is NIF's negation") {
	// At the centre the three legs are symmetric about z: a +z force loads all three motors
	// equally; the words are the negated torques.
	MotorWords words;
	REQUIRE(falcon_force_to_motor_words(FALCON_KINEMATIC_CENTRE, { 0, 0, 4.0 }, words));
	CHECK(words.word[0] == words.word[1]);
	CHECK(words.word[1] == words.word[2]);
	Mat3 dp_dtheta;
	REQUIRE(falcon_position_jacobian(FALCON_KINEMATIC_CENTRE, dp_dtheta));
	const double torque = (dp_dtheta.transposed() * Vec3{ 0, 0, 4.0 }).x;
	CHECK(torque != 0.0);
	CHECK((words.word[0] > 0) == (torque < 0)); // Negated.
}

TEST_CASE("falcon kinematics: huge forces scale all torques together (|tau| <= 30, then int16), finite and clamped") {
	const Vec3 p{ -0.02, 0.01, 0.14 };
	const Vec3 force{ 500.0, -250.0, 120.0 };
	MotorWords small;
	REQUIRE(falcon_force_to_motor_words(p, force * 0.001, small));
	MotorWords big;
	REQUIRE(falcon_force_to_motor_words(p, force, big));
	CHECK(big.word_limited);
	int largest = 0;
	for (int i = 0; i < 3; ++i) {
		largest = std::max(largest, std::abs(static_cast<int>(big.word[i])));
	}
	CHECK(largest == 32767);
	// Same direction: the words are proportional to the small force's.
	const int small_largest = std::max({ std::abs(static_cast<int>(small.word[0])), std::abs(static_cast<int>(small.word[1])),
			std::abs(static_cast<int>(small.word[2])) });
	REQUIRE(small_largest > 100);
	for (int i = 0; i < 3; ++i) {
		CHECK(static_cast<double>(big.word[i]) / 32767.0 ==
				doctest::Approx(static_cast<double>(small.word[i]) / small_largest).epsilon(0.01));
	}
	// NIF's torque limit: 30 * 10000 exceeds int16, so both flags go up for an absurd force.
	MotorWords absurd;
	REQUIRE(falcon_force_to_motor_words(p, force * 1e4, absurd));
	CHECK(absurd.torque_limited);
	CHECK(absurd.word_limited);
	for (int i = 0; i < 3; ++i) {
		CHECK(absurd.word[i] >= -32768);
		CHECK(absurd.word[i] <= 32767);
	}
	REQUIRE(falcon_force_to_motor_words(p, { 1e308, 1e308, -1e308 }, absurd));
}

TEST_CASE("falcon axes: kinematic frame to device space is a translation by the centre") {
	CHECK(falcon_to_device_position(FALCON_KINEMATIC_CENTRE) == Vec3{});
	// Grip pushed right (kinematic +x) -> device +x; up -> +y; pulled out toward the user
	// (kinematic z grows) -> device +z.
	CHECK(falcon_to_device_position({ 0.02, 0.0, 0.125 }) == Vec3{ 0.02, 0.0, 0.0 });
	CHECK(falcon_to_device_position({ 0.0, 0.03, 0.125 }).y == doctest::Approx(0.03));
	CHECK(falcon_to_device_position({ 0.0, 0.0, 0.170 }).z == doctest::Approx(0.045));
	CHECK(device_to_falcon_position({ 0.0, -0.01, 0.0 }).z == doctest::Approx(0.125));
	CHECK(device_to_falcon_direction({ 0.0, 2.0, 0.0 }) == Vec3{ 0.0, 2.0, 0.0 });
}
