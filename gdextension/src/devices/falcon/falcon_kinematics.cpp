#include "devices/falcon/falcon_kinematics.h"

#include <cmath>
#include <numbers>

namespace haptics::falcon {

namespace {

constexpr double PI = std::numbers::pi;
// Leg angles around z (docs/devices/falcon.md, "Kinematics"): 105, -15, -135 degrees.
constexpr double LEG_PHI[3] = { PI / 2.0 + PI / 12.0, -PI / 6.0 + PI / 12.0, -5.0 * PI / 6.0 + PI / 12.0 };

// Below these the configuration is singular (a leg stretched straight, or thigh and shin
// aligned): the Jacobian blows up and force directions become meaningless.
constexpr double MIN_SIN_THETA3 = 1e-3;
constexpr double MIN_SIN_THETA2_MINUS_1 = 1e-3;
constexpr double COS_TOLERANCE = 1e-12; // Rounding slack before acos.

constexpr int32_t FK_MAX_ITERATIONS = 30;
constexpr int32_t FK_MAX_HALVINGS = 12;
constexpr double FK_ANGLE_TOLERANCE_RAD = 1e-12;
constexpr double FK_MAX_STEP_M = 0.05; // A Newton step longer than this is cut: stay in the model's domain.

const char *const LEG_NAMES[3] = { "leg 1", "leg 2", "leg 3" };

Status solve_leg(int32_t p_leg, const Vec3 &p_position, LegAngles &r_leg) {
	const double phi = LEG_PHI[p_leg];
	const double cos_phi = std::cos(phi);
	const double sin_phi = std::sin(phi);
	const double u = cos_phi * p_position.x + sin_phi * p_position.y - FALCON_R;
	const double v = -sin_phi * p_position.x + cos_phi * p_position.y - FALCON_S;
	const double w = p_position.z;

	const double cos_t3 = (v + FALCON_F) / FALCON_B;
	if (!(std::fabs(cos_t3) <= 1.0)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "Falcon IK: (%g, %g, %g) m unreachable: %s's shin cannot span %g m",
				p_position.x, p_position.y, p_position.z, LEG_NAMES[p_leg], v + FALCON_F);
	}
	const double t3 = std::acos(cos_t3);
	const double length = FALCON_D + FALCON_E + FALCON_B * std::sin(t3);

	// (u + c - a cos t1)^2 + (w - a sin t1)^2 = L^2, with T = tan(t1 / 2).
	const double uc = u + FALCON_C;
	const double k = uc * uc + w * w + FALCON_A * FALCON_A - length * length;
	const double l0 = k - 2.0 * FALCON_A * uc;
	const double l1 = -4.0 * FALCON_A * w;
	const double l2 = k + 2.0 * FALCON_A * uc;
	const double discriminant = l1 * l1 - 4.0 * l0 * l2;
	if (!(discriminant >= 0.0) || std::fabs(l2) < 1e-15) {
		return Status::error(StatusCode::OUT_OF_RANGE, "Falcon IK: (%g, %g, %g) m unreachable: %s's thigh cannot reach it",
				p_position.x, p_position.y, p_position.z, LEG_NAMES[p_leg]);
	}
	const double t1 = 2.0 * std::atan((-l1 - std::sqrt(discriminant)) / (2.0 * l2));

	const double along = w - FALCON_A * std::sin(t1);
	double cos_t2 = (uc - FALCON_A * std::cos(t1)) / length;
	if (!(std::fabs(cos_t2) <= 1.0 + COS_TOLERANCE) || along < 0.0) {
		// along < 0 would need sin(t2) < 0: the mirrored branch, not the Falcon's.
		return Status::error(StatusCode::OUT_OF_RANGE, "Falcon IK: (%g, %g, %g) m outside the model's branch at %s",
				p_position.x, p_position.y, p_position.z, LEG_NAMES[p_leg]);
	}
	cos_t2 = cos_t2 > 1.0 ? 1.0 : (cos_t2 < -1.0 ? -1.0 : cos_t2);
	r_leg = LegAngles{ t1, std::acos(cos_t2), t3 };
	return Status::success();
}

} // namespace

Vec3 Mat3::operator*(const Vec3 &p_v) const {
	return { m[0][0] * p_v.x + m[0][1] * p_v.y + m[0][2] * p_v.z, m[1][0] * p_v.x + m[1][1] * p_v.y + m[1][2] * p_v.z,
		m[2][0] * p_v.x + m[2][1] * p_v.y + m[2][2] * p_v.z };
}

Mat3 Mat3::transposed() const {
	Mat3 t;
	for (int i = 0; i < 3; ++i) {
		for (int j = 0; j < 3; ++j) {
			t.m[i][j] = m[j][i];
		}
	}
	return t;
}

double Mat3::determinant() const {
	return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
			m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool invert(const Mat3 &p_matrix, Mat3 &r_inverse, double p_min_determinant) {
	const double det = p_matrix.determinant();
	if (!(std::fabs(det) >= p_min_determinant) || !std::isfinite(det)) {
		return false;
	}
	const auto &a = p_matrix.m;
	Mat3 inverse;
	// Adjugate over the determinant.
	inverse.m[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
	inverse.m[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
	inverse.m[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
	inverse.m[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
	inverse.m[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
	inverse.m[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
	inverse.m[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
	inverse.m[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
	inverse.m[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
	r_inverse = inverse;
	return true;
}

double encoder_to_theta_deg(int32_t p_count) {
	return FALCON_THETA_OFFSET_DEG + FALCON_DEG_PER_COUNT * static_cast<double>(p_count);
}

double encoder_to_theta_rad(int32_t p_count) {
	return encoder_to_theta_deg(p_count) * (PI / 180.0);
}

int16_t theta_rad_to_encoder(double p_theta_rad) {
	const double count = (p_theta_rad * (180.0 / PI) - FALCON_THETA_OFFSET_DEG) / FALCON_DEG_PER_COUNT;
	if (!(count > -32768.0)) {
		return INT16_MIN;
	}
	if (!(count < 32767.0)) {
		return INT16_MAX;
	}
	return static_cast<int16_t>(std::lround(count));
}

Status falcon_inverse_kinematics(const Vec3 &p_position, FalconAngles &r_angles) {
	if (!is_finite(p_position)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon IK: position not finite (%g, %g, %g)", p_position.x,
				p_position.y, p_position.z);
	}
	FalconAngles angles;
	for (int32_t leg = 0; leg < 3; ++leg) {
		const Status solved = solve_leg(leg, p_position, angles.leg[leg]);
		if (!solved) {
			return solved;
		}
	}
	r_angles = angles;
	return Status::success();
}

Status falcon_angle_jacobian(const FalconAngles &p_angles, Mat3 &r_dtheta_dp) {
	Mat3 jacobian;
	for (int32_t leg = 0; leg < 3; ++leg) {
		const LegAngles &angles = p_angles.leg[leg];
		const double sin_t3 = std::sin(angles.theta3);
		const double sin_t21 = std::sin(angles.theta2 - angles.theta1);
		if (!(std::fabs(sin_t3) >= MIN_SIN_THETA3) || !(std::fabs(sin_t21) >= MIN_SIN_THETA2_MINUS_1)) {
			return Status::error(StatusCode::OUT_OF_RANGE, "Falcon Jacobian: %s is at a singular configuration", LEG_NAMES[leg]);
		}
		const double scale = 1.0 / (FALCON_A * sin_t21);
		const double du = std::cos(angles.theta2) * scale;
		const double dv = std::cos(angles.theta3) / sin_t3 * scale;
		const double dw = std::sin(angles.theta2) * scale;
		// u = cos(phi) x + sin(phi) y - r,  v = -sin(phi) x + cos(phi) y - s,  w = z.
		const double cos_phi = std::cos(LEG_PHI[leg]);
		const double sin_phi = std::sin(LEG_PHI[leg]);
		jacobian.m[leg][0] = du * cos_phi - dv * sin_phi;
		jacobian.m[leg][1] = du * sin_phi + dv * cos_phi;
		jacobian.m[leg][2] = dw;
	}
	r_dtheta_dp = jacobian;
	return Status::success();
}

Status falcon_position_jacobian(const Vec3 &p_position, Mat3 &r_dp_dtheta) {
	FalconAngles angles;
	Status status = falcon_inverse_kinematics(p_position, angles);
	Mat3 dtheta_dp;
	if (status) {
		status = falcon_angle_jacobian(angles, dtheta_dp);
	}
	if (!status) {
		return status;
	}
	if (!invert(dtheta_dp, r_dp_dtheta, 1e-6)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "Falcon Jacobian: singular at (%g, %g, %g) m", p_position.x,
				p_position.y, p_position.z);
	}
	return Status::success();
}

Status falcon_forward_kinematics(const double p_theta1[3], const Vec3 &p_guess, Vec3 &r_position, int32_t *r_iterations) {
	if (!std::isfinite(p_theta1[0]) || !std::isfinite(p_theta1[1]) || !std::isfinite(p_theta1[2])) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon FK: angles not finite");
	}
	Vec3 position = is_finite(p_guess) ? p_guess : FALCON_KINEMATIC_CENTRE;
	FalconAngles angles;
	if (!falcon_inverse_kinematics(position, angles)) {
		position = FALCON_KINEMATIC_CENTRE; // A guess outside the model: restart from the middle.
		falcon_inverse_kinematics(position, angles);
	}
	const auto error_of = [p_theta1](const FalconAngles &p_angles) {
		const Vec3 error{ p_theta1[0] - p_angles.leg[0].theta1, p_theta1[1] - p_angles.leg[1].theta1,
			p_theta1[2] - p_angles.leg[2].theta1 };
		return error;
	};
	Vec3 error = error_of(angles);
	for (int32_t iteration = 0; iteration < FK_MAX_ITERATIONS; ++iteration) {
		if (length(error) < FK_ANGLE_TOLERANCE_RAD) {
			if (r_iterations) {
				*r_iterations = iteration;
			}
			r_position = position;
			return Status::success();
		}
		Mat3 dtheta_dp;
		Mat3 dp_dtheta;
		if (!falcon_angle_jacobian(angles, dtheta_dp) || !invert(dtheta_dp, dp_dtheta, 1e-6)) {
			break;
		}
		Vec3 step = dp_dtheta * error;
		const double step_length = length(step);
		if (step_length > FK_MAX_STEP_M) {
			step = step * (FK_MAX_STEP_M / step_length);
		}
		// Halve the step until it lands inside the model and reduces the error.
		bool moved = false;
		for (int32_t halving = 0; halving < FK_MAX_HALVINGS && !moved; ++halving) {
			FalconAngles next_angles;
			const Vec3 next = position + step;
			if (falcon_inverse_kinematics(next, next_angles)) {
				const Vec3 next_error = error_of(next_angles);
				if (length(next_error) < length(error)) {
					position = next;
					angles = next_angles;
					error = next_error;
					moved = true;
				}
			}
			step = step * 0.5;
		}
		if (!moved) {
			// At the floating-point floor the error can no longer shrink: accept it when small.
			if (length(error) < 1e-9) {
				if (r_iterations) {
					*r_iterations = iteration;
				}
				r_position = position;
				return Status::success();
			}
			break;
		}
	}
	return Status::error(StatusCode::OUT_OF_RANGE, "Falcon FK: no position for motor angles (%.2f, %.2f, %.2f) deg",
			p_theta1[0] * 180.0 / PI, p_theta1[1] * 180.0 / PI, p_theta1[2] * 180.0 / PI);
}

Status falcon_force_to_motor_words(const Vec3 &p_position, const Vec3 &p_force_n, MotorWords &r_words) {
	if (!is_finite(p_force_n)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon force not finite (%g, %g, %g)", p_force_n.x, p_force_n.y,
				p_force_n.z);
	}
	Mat3 dp_dtheta;
	const Status jacobian = falcon_position_jacobian(p_position, dp_dtheta);
	if (!jacobian) {
		return jacobian;
	}
	Vec3 torque = dp_dtheta.transposed() * p_force_n; // Virtual work: tau = J_p^T F.
	MotorWords words;
	const double largest_torque = std::fmax(std::fabs(torque.x), std::fmax(std::fabs(torque.y), std::fabs(torque.z)));
	if (largest_torque > FALCON_MAX_JOINT_TORQUE) {
		torque = torque * (FALCON_MAX_JOINT_TORQUE / largest_torque);
		words.torque_limited = true;
	}
	Vec3 scaled = torque * -FALCON_TORQUE_TO_WORD;
	const double largest_word = std::fmax(std::fabs(scaled.x), std::fmax(std::fabs(scaled.y), std::fabs(scaled.z)));
	if (largest_word > 32767.0) {
		scaled = scaled * (32767.0 / largest_word);
		words.word_limited = true;
	}
	const double values[3] = { scaled.x, scaled.y, scaled.z };
	for (int i = 0; i < 3; ++i) {
		const double clamped = values[i] > 32767.0 ? 32767.0 : (values[i] < -32768.0 ? -32768.0 : values[i]);
		words.word[i] = static_cast<int16_t>(std::lround(clamped));
	}
	r_words = words;
	return Status::success();
}

Status falcon_motor_words_to_force(const Vec3 &p_position, const int16_t p_words[3], Vec3 &r_force_n) {
	FalconAngles angles;
	Mat3 dtheta_dp;
	Status status = falcon_inverse_kinematics(p_position, angles);
	if (status) {
		status = falcon_angle_jacobian(angles, dtheta_dp);
	}
	if (!status) {
		return status;
	}
	const Vec3 torque = Vec3{ static_cast<double>(p_words[0]), static_cast<double>(p_words[1]),
		static_cast<double>(p_words[2]) } /
			-FALCON_TORQUE_TO_WORD;
	// tau = J_p^T F  =>  F = J_p^-T tau = (dt1/dp)^T tau.
	r_force_n = dtheta_dp.transposed() * torque;
	return Status::success();
}

} // namespace haptics::falcon
