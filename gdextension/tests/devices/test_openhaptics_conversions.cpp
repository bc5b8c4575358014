// HDAPI arrays -> device space (docs/devices/openhaptics.md): mm -> m centred on the usable box, the
// column-major transform -> quaternion, the plausible-position bound, and the last force
// guard before the motors.

#include "devices/openhaptics/hd_conversions.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>

using namespace haptics;
using namespace haptics::openhaptics;

namespace {

// Column-major 4x4 from a unit quaternion (the textbook formula) plus a translation.
void transform_from_quaternion(const Orientation &p_q, const Vec3 &p_translation_mm, double r_m[16]) {
	const double w = p_q.w, x = p_q.x, y = p_q.y, z = p_q.z;
	const double r[3][3] = {
		{ 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w) },
		{ 2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w) },
		{ 2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y) },
	};
	std::memset(r_m, 0, 16 * sizeof(double));
	for (int column = 0; column < 3; ++column) {
		for (int row = 0; row < 3; ++row) {
			r_m[4 * column + row] = r[row][column];
		}
	}
	r_m[12] = p_translation_mm.x;
	r_m[13] = p_translation_mm.y;
	r_m[14] = p_translation_mm.z;
	r_m[15] = 1.0;
}

void check_same_rotation(const Orientation &p_a, const Orientation &p_b) {
	// q and -q are the same rotation; ours has w >= 0.
	const double dot = p_a.w * p_b.w + p_a.x * p_b.x + p_a.y * p_b.y + p_a.z * p_b.z;
	CHECK(std::abs(dot) == doctest::Approx(1.0).epsilon(1e-12));
}

} // namespace

TEST_CASE("openhaptics: the usable workspace box gives a centre and an inscribed radius in metres") {
	const double box_mm[6] = { -80.0, -50.0, -40.0, 80.0, 70.0, 60.0 };
	HdWorkspace workspace;
	REQUIRE(workspace_from_hd_box(box_mm, workspace));
	CHECK(workspace.centre_m.x == doctest::Approx(0.0));
	CHECK(workspace.centre_m.y == doctest::Approx(0.010));
	CHECK(workspace.centre_m.z == doctest::Approx(0.010));
	CHECK(workspace.half_extent_m.x == doctest::Approx(0.080));
	CHECK(workspace.half_extent_m.y == doctest::Approx(0.060));
	CHECK(workspace.half_extent_m.z == doctest::Approx(0.050));
	CHECK(workspace.radius_m == doctest::Approx(0.050)); // The smallest half extent.
}

TEST_CASE("openhaptics: a workspace box that is not a box is refused, naming the parameter and axis") {
	const double nan = std::numeric_limits<double>::quiet_NaN();
	HdWorkspace workspace;
	const double inverted[6] = { -80.0, 70.0, -40.0, 80.0, -50.0, 60.0 };
	const Status status = workspace_from_hd_box(inverted, workspace);
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::strstr(status.message(), "HD_USABLE_WORKSPACE_DIMENSIONS: y") != nullptr);
	const double not_finite[6] = { -80.0, -50.0, nan, 80.0, 70.0, 60.0 };
	CHECK(std::strstr(workspace_from_hd_box(not_finite, workspace).message(), ": z") != nullptr);
	const double flat[6] = { 10.0, -50.0, -40.0, 10.0, 70.0, 60.0 };
	CHECK_FALSE(workspace_from_hd_box(flat, workspace));
}

TEST_CASE("openhaptics: positions in mm become metres from the workspace centre - velocities mm/s -> m/s") {
	const double position_mm[3] = { 30.0, -10.0, 50.0 };
	const Vec3 position = position_from_hd(position_mm, Vec3{ 0.0, 0.010, 0.010 });
	CHECK(position.x == doctest::Approx(0.030));
	CHECK(position.y == doctest::Approx(-0.020));
	CHECK(position.z == doctest::Approx(0.040));
	const double velocity_mm_s[3] = { 100.0, -200.0, 300.0 };
	const Vec3 velocity = velocity_from_hd(velocity_mm_s);
	CHECK(velocity.x == doctest::Approx(0.1));
	CHECK(velocity.y == doctest::Approx(-0.2));
	CHECK(velocity.z == doctest::Approx(0.3));
}

TEST_CASE("openhaptics: a position is plausible when finite and within MAX_PLAUSIBLE_POSITION_M of the centre") {
	CHECK(MAX_PLAUSIBLE_POSITION_M == 10.0);
	CHECK(position_plausible(Vec3{ 0.2, -0.1, 0.1 })); // A Touch's reach.
	CHECK(position_plausible(Vec3{ 0.0, 0.0, -10.0 }));
	CHECK_FALSE(position_plausible(Vec3{ 0.0, 0.0, -10.001 }));
	CHECK_FALSE(position_plausible(Vec3{ 6.0, 6.0, 6.0 })); // Each axis under 10 m, the distance not.
	CHECK_FALSE(position_plausible(Vec3{ 1e300, 1e300, 0.0 })); // Its length overflows to infinity.
	CHECK_FALSE(position_plausible(Vec3{ 0.0, std::numeric_limits<double>::quiet_NaN(), 0.0 }));
}

TEST_CASE("openhaptics: the column-major transform's rotation becomes the quaternion - translation ignored") {
	double m[16];
	transform_from_quaternion(Orientation{}, Vec3{ 5, 6, 7 }, m);
	const Orientation identity = orientation_from_hd_transform(m);
	CHECK(identity.w == doctest::Approx(1.0));
	CHECK(identity.x == doctest::Approx(0.0));

	// 90 degrees about +y, written out by hand in column-major order: the columns are the
	// images of x (-> -z), y (-> y) and z (-> x). Read row-major, this is -90 degrees.
	const double about_y[16] = { 0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 12, 13, 14, 1 };
	const Orientation q = orientation_from_hd_transform(about_y);
	CHECK(q.w == doctest::Approx(std::sqrt(0.5)));
	CHECK(q.x == doctest::Approx(0.0));
	CHECK(q.y == doctest::Approx(std::sqrt(0.5)));
	CHECK(q.z == doctest::Approx(0.0));

	// Every branch of the conversion (trace > 0 and each largest diagonal), w >= 0.
	const Orientation cases[] = {
		{ 0.0, 1.0, 0.0, 0.0 }, // 180 about x
		{ 0.0, 0.0, 1.0, 0.0 }, // 180 about y
		{ 0.0, 0.0, 0.0, 1.0 }, // 180 about z
		{ 0.5, 0.5, 0.5, 0.5 }, // 120 about (1, 1, 1)
		{ 0.1, -0.7, 0.7, std::sqrt(1.0 - 0.01 - 0.98) },
		{ 0.9, 0.1, -0.3, std::sqrt(1.0 - 0.81 - 0.01 - 0.09) },
	};
	for (const Orientation &expected : cases) {
		transform_from_quaternion(expected, Vec3{}, m);
		const Orientation got = orientation_from_hd_transform(m);
		check_same_rotation(got, expected);
		CHECK(got.w >= 0.0);
	}
}

TEST_CASE("openhaptics: a transform without a rotation gives identity, not NaN") {
	double zeros[16] = {};
	const Orientation from_zero = orientation_from_hd_transform(zeros);
	CHECK(from_zero.w == 1.0);
	double with_nan[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
	with_nan[5] = std::numeric_limits<double>::quiet_NaN();
	const Orientation from_nan = orientation_from_hd_transform(with_nan);
	CHECK(from_nan.w == 1.0);
	CHECK(from_nan.x == 0.0);
}

TEST_CASE("openhaptics: the force guard caps the continuous share, then the total, and zeroes non-finite") {
	const double continuous = 0.88;
	const double peak = 3.3;
	const Vec3 small = bounded_force(ForceCommand{ { 0.1, -0.2, 0.3 }, {} }, continuous, peak);
	CHECK(small == Vec3{ 0.1, -0.2, 0.3 });

	const Vec3 capped = bounded_force(ForceCommand{ { 0.0, 2.0, 0.0 }, {} }, continuous, peak);
	CHECK(capped.y == doctest::Approx(0.88));
	CHECK(capped.x == 0.0);

	// A transient rides above the continuous cap: 1 N continuous -> 0.88, plus 2 N impact.
	const Vec3 with_impact = bounded_force(ForceCommand{ { 3.0, 0.0, 0.0 }, { 2.0, 0.0, 0.0 } }, continuous, peak);
	CHECK(with_impact.x == doctest::Approx(2.88));

	const Vec3 total = bounded_force(ForceCommand{ { 10.0, 0.0, 0.0 }, { 10.0, 0.0, 0.0 } }, continuous, peak);
	CHECK(total.x == doctest::Approx(3.3));

	const Vec3 uncapped = bounded_force(ForceCommand{ { 2.0, 0.0, 0.0 }, {} }, 0.0, peak);
	CHECK(uncapped.x == doctest::Approx(2.0));

	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	CHECK(bounded_force(ForceCommand{ { nan, 0.0, 0.0 }, {} }, continuous, peak) == Vec3{});
	CHECK(bounded_force(ForceCommand{ { 0.1, 0.0, 0.0 }, { inf, 0.0, 0.0 } }, continuous, peak) == Vec3{});
	CHECK(bounded_force(ForceCommand{ { 0.1, 0.0, 0.0 }, {} }, continuous, 0.0) == Vec3{});
}
