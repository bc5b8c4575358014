// The vehicle renderer's tyre model (renderers/vehicle/brush_tyre.h) against values worked by
// hand from its formulas (docs/vehicle.md): a passenger car's front tyre, F_z = 4000 N,
// C_F_alpha / F_z = 15 /rad, a = 0.07 m, t_m = 0.02 m, on grip 1 unless said otherwise.
//   theta = C / (3 mu) = 5,  lambda = theta tan(alpha)
//   F_y  = mu F_z lambda (3 - 3 |lambda| + lambda^2)
//   M_z' = -mu F_z a lambda (1 - |lambda|)^3,   M_kp = M_z' - t_m F_y

#include "renderers/vehicle/brush_tyre.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace haptics;

namespace {

constexpr double LOAD_N = 4000.0;
constexpr double NM = 0.01; // Tolerance on a torque, N m.
constexpr double N = 0.05; // On a force, N.

double degrees(double p_degrees) {
	return p_degrees * std::numbers::pi / 180.0;
}

} // namespace

TEST_CASE("brush tyre: 2 degrees of slip, below the aligning torque's peak") {
	// tan 2 deg = 0.0349208, lambda = 0.174604;
	// F_y  = 4000 x 0.174604 x (3 - 0.523811 + 0.030486 = 2.506675) = 1750.70 N
	// M_z' = -4000 x 0.07 x 0.174604 x (0.825396^3 = 0.562325)      = -27.49 N m
	// M_kp = -27.49 - 0.02 x 1750.70                                  = -62.51 N m
	const TyreForces forces = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(2.0), 1.0);
	CHECK(forces.slide_fraction == doctest::Approx(0.174604).epsilon(1e-5));
	CHECK(forces.lateral_force_n == doctest::Approx(1750.70).epsilon(N / 1750.70));
	CHECK(forces.self_aligning_nm == doctest::Approx(-27.49).epsilon(NM / 27.49));
	CHECK(forces.kingpin_torque_nm == doctest::Approx(-62.51).epsilon(NM / 62.51));
	// The pneumatic trail is near a/3 = 23.3 mm at small slip: here 27.49 / 1750.70 = 15.7 mm,
	// already shortened by the sliding at the patch's rear.
	CHECK(-forces.self_aligning_nm / forces.lateral_force_n == doctest::Approx(0.0157).epsilon(0.01));
}

TEST_CASE("brush tyre: the sign follows the slip, and the torque returns the wheel toward its path") {
	const TyreForces left = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(2.0), 1.0);
	const TyreForces right = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(-2.0), 1.0);
	// Velocity to the right of the wheel (alpha > 0, a left turn): pushed left, turned right.
	CHECK(left.lateral_force_n > 0.0);
	CHECK(left.kingpin_torque_nm < 0.0);
	CHECK(right.lateral_force_n == doctest::Approx(-left.lateral_force_n));
	CHECK(right.kingpin_torque_nm == doctest::Approx(-left.kingpin_torque_nm));
	const TyreForces straight = brush_tyre_forces(BrushTyre{}, LOAD_N, 0.0, 1.0);
	CHECK(straight.lateral_force_n == 0.0);
	CHECK(straight.kingpin_torque_nm == 0.0);
}

TEST_CASE("brush tyre: past the peak the self-aligning torque falls while the force still rises") {
	// 8 deg: tan = 0.140541, lambda = 0.702704;
	// F_y  = 4000 x 0.702704 x (3 - 2.108113 + 0.493793 = 1.385681) = 3894.89 N
	// M_z' = -280 x 0.702704 x (0.297296^3 = 0.026276)               = -5.17 N m
	// M_kp = -5.17 - 0.02 x 3894.89                                   = -83.07 N m
	const TyreForces forces = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(8.0), 1.0);
	CHECK(forces.lateral_force_n == doctest::Approx(3894.89).epsilon(N / 3894.89));
	CHECK(forces.self_aligning_nm == doctest::Approx(-5.17).epsilon(NM / 5.17));
	CHECK(forces.kingpin_torque_nm == doctest::Approx(-83.07).epsilon(NM / 83.07));
	const TyreForces two = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(2.0), 1.0);
	CHECK(std::abs(forces.self_aligning_nm) < std::abs(two.self_aligning_nm) / 5.0);
	CHECK(forces.lateral_force_n > two.lateral_force_n);
}

TEST_CASE("brush tyre: sliding, the force is mu F_z and only the mechanical trail is left") {
	// 15 deg: lambda = 5 x 0.267949 = 1.34 >= 1: F_y = 4000 N, M_z' = 0, M_kp = -0.02 x 4000.
	const TyreForces forces = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(15.0), 1.0);
	CHECK(forces.slide_fraction > 1.0);
	CHECK(forces.lateral_force_n == doctest::Approx(4000.0));
	CHECK(forces.self_aligning_nm == 0.0);
	CHECK(forces.kingpin_torque_nm == doctest::Approx(-80.0));
}

TEST_CASE("brush tyre: grip scales the force and the slip at which the tyre lets go") {
	// mu = 0.6, F_z = 3000 N, 3 deg: theta = 15 / 1.8 = 8.333333, lambda = 8.333333 x 0.052408
	// = 0.436731; F_y = 1800 x 0.436731 x 1.880540 = 1478.32 N;
	// M_z' = -1800 x 0.07 x 0.436731 x (0.563269^3 = 0.178709) = -9.83 N m;
	// M_kp = -9.83 - 0.02 x 1478.32 = -39.40 N m.
	const TyreForces forces = brush_tyre_forces(BrushTyre{}, 3000.0, degrees(3.0), 0.6);
	CHECK(forces.slide_fraction == doctest::Approx(0.436731).epsilon(1e-5));
	CHECK(forces.lateral_force_n == doctest::Approx(1478.32).epsilon(N / 1478.32));
	CHECK(forces.self_aligning_nm == doctest::Approx(-9.83).epsilon(NM / 9.83));
	CHECK(forces.kingpin_torque_nm == doctest::Approx(-39.40).epsilon(NM / 39.40));
}

TEST_CASE("brush tyre: rolling backward, the mechanical trail leads") {
	// The tyre's own part is the same (2 deg: F_y 1750.70 N, M_z' -27.49 N m); the trail's
	// changes sign: M_kp = -27.49 + 0.02 x 1750.70 = +7.52 N m.
	const TyreForces forces = brush_tyre_forces(BrushTyre{}, LOAD_N, degrees(2.0), 1.0, true);
	CHECK(forces.self_aligning_nm == doctest::Approx(-27.49).epsilon(NM / 27.49));
	CHECK(forces.kingpin_torque_nm == doctest::Approx(7.52).epsilon(NM / 7.52));
}

TEST_CASE("brush tyre: the peak of the steering axis's torque, in closed form and by search") {
	// lambda* = (a + 3 t_m) / (4 a) = (0.07 + 0.06) / 0.28 = 0.464286;
	// |M_kp|max / F_z = 0.07 x 0.464286 x 0.535714^3 + 0.06 x 0.464286 x (1 - 0.464286 + 0.071854)
	//                 = 0.006537 + 0.016385 = 0.021922 m.
	const BrushTyre tyre;
	CHECK(brush_peak_slide_fraction(tyre) == doctest::Approx(0.464286).epsilon(1e-5));
	CHECK(brush_peak_torque_per_load(tyre) == doctest::Approx(0.021922).epsilon(1e-4));
	double best = 0.0;
	for (int i = 0; i <= 20000; ++i) {
		const double alpha = std::atan((i / 10000.0) / 5.0);
		best = std::max(best, std::abs(brush_tyre_forces(tyre, 1.0, alpha, 1.0).kingpin_torque_nm));
	}
	CHECK(best == doctest::Approx(brush_peak_torque_per_load(tyre)).epsilon(1e-6));
	// A trail as long as the half-length: the peak is the sliding plateau, t_m mu F_z.
	const BrushTyre long_trail{ 15.0, 0.05, 0.05 };
	CHECK(brush_peak_slide_fraction(long_trail) == 1.0);
	CHECK(brush_peak_torque_per_load(long_trail) == doctest::Approx(0.05));
}

TEST_CASE("brush tyre: no load or no grip is no force, and every slip in range is finite") {
	CHECK(brush_tyre_forces(BrushTyre{}, 0.0, 0.1, 1.0).kingpin_torque_nm == 0.0);
	CHECK(brush_tyre_forces(BrushTyre{}, 4000.0, 0.1, 0.0).lateral_force_n == 0.0);
	for (double alpha = -1.5; alpha <= 1.5; alpha += 0.01) {
		const TyreForces forces = brush_tyre_forces(BrushTyre{}, 1e6, alpha, 100.0);
		CHECK(std::isfinite(forces.kingpin_torque_nm));
		CHECK(std::abs(forces.lateral_force_n) <= 1e8 + 1e-3);
	}
}
