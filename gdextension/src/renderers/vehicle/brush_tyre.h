#pragma once

// A steered tyre's lateral force and its torque about the steering axis: the brush model with
// a parabolic pressure distribution (H. B. Pacejka, "Tire and Vehicle Dynamics", 3rd ed.,
// Butterworth-Heinemann 2012, section 3.2), plus the mechanical trail of the steering
// geometry. docs/vehicle.md derives the peak and gives worked numbers.
//
// Axes (Pacejka's: x forward along the wheel's rolling direction, y left, z up). alpha is
// the angle from the rolling direction to the contact's velocity, positive when the velocity
// points to the right (a wheel steered left of its path); torques about z, positive turning
// the wheel left.
//
//   theta  = C / (3 mu)                 C = C_F_alpha / F_z, the cornering coefficient
//   lambda = theta tan(alpha)           0 rolling straight, 1 the whole patch sliding
//   |lambda| < 1:
//     F_y  =  mu F_z (3 lambda - 3 lambda |lambda| + lambda^3)
//     M_z' = -mu F_z a lambda (1 - |lambda|)^3          (the self-aligning torque)
//   |lambda| >= 1:  F_y = mu F_z sgn(lambda),  M_z' = 0
//   M_kp = M_z' - s t_m F_y              s = +1 rolling forward, -1 backward
//
// For small alpha, F_y = C_F_alpha alpha and M_z' = -(a/3) F_y: the pneumatic trail is a third
// of the half-length. M_z' rises with the slip, peaks at lambda = 1/4 and falls to zero as the
// patch slides: the steering going light as the front lets go. The mechanical trail t_m
// (the contact centre behind the steering axis's ground point) adds -t_m F_y, which stays
// while the tyre slides. Both turn the wheel toward its velocity when it rolls forward;
// rolling backward the mechanical trail leads and turns it away.
//
// The torque of the axle peaks where d/dlambda [a lambda (1-lambda)^3 + 3 t_m (lambda -
// lambda^2 + lambda^3/3)] = (1-lambda)^2 (a (1 - 4 lambda) + 3 t_m) = 0:
//   lambda* = min(1, (a + 3 t_m) / (4 a)),
//   |M_kp|max = mu F_z (a lambda* (1-lambda*)^3 + 3 t_m lambda* (1 - lambda* + lambda*^2/3)).
//
// Pure functions of their arguments; no allocation; finite for every finite input in the
// frame's ranges (a zero load or grip gives zero).

namespace haptics {

struct BrushTyre {
	double cornering_coefficient_per_rad = 15.0; // C_F_alpha / F_z
	double contact_half_length_m = 0.07; // a
	double mechanical_trail_m = 0.02; // t_m
};

struct TyreForces {
	double lateral_force_n = 0.0; // F_y, positive to the left.
	double self_aligning_nm = 0.0; // M_z', about the contact centre.
	double kingpin_torque_nm = 0.0; // M_kp, about the steering axis.
	double slide_fraction = 0.0; // |lambda|: 1 and over, the whole patch slides.
};

// p_load_n F_z >= 0, p_slip_angle_rad alpha in [-1.5, 1.5], p_grip mu >= 0.
TyreForces brush_tyre_forces(const BrushTyre &p_tyre, double p_load_n, double p_slip_angle_rad, double p_grip,
		bool p_rolling_backward = false);

// lambda* above: where the magnitude of M_kp peaks (rolling forward).
double brush_peak_slide_fraction(const BrushTyre &p_tyre);

// |M_kp|max per newton of load at grip 1 (metres): the peak torque is this times mu F_z.
double brush_peak_torque_per_load(const BrushTyre &p_tyre);

} // namespace haptics
