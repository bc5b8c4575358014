#include "renderers/pong/pong_validation.h"

#include "core/base/value_checks.h"
#include "core/servo/servo_rate.h"

#include <cmath>
#include <cstdio>

namespace haptics {

namespace {

// Far beyond any court the field table allows, close enough to keep float rendering sane.
constexpr double MAX_WORLD_M = 1000.0;
constexpr double MAX_SPEED_M_PER_S = 1000.0; // Capped to max_ball_speed by the servo anyway.
constexpr double MAX_SPIN_RAD_PER_S = 1e5; // Likewise max_spin.
constexpr double MAX_EFFECT_FORCE_N = 100.0; // The safety stage caps at the device's peak.
constexpr double MAX_EFFECT_DURATION_S = 600.0;
// A sample older than this is not a network delay but a lost peer (issue 11 notices those in
// about a second).
constexpr double MAX_POSE_AGE_S = 10.0;

// A player of a court of p_players (0..p_players - 1), or -1 when p_allow_none.
Status check_player(const char *p_name, int32_t p_player, bool p_allow_none, int p_players) {
	if ((p_player >= 0 && p_player < p_players) || (p_allow_none && p_player == -1)) {
		return Status::success();
	}
	return Status::error(StatusCode::OUT_OF_RANGE, "%s must be %s0..%d (got %d)", p_name, p_allow_none ? "-1 or " : "",
			p_players - 1, p_player);
}

} // namespace

Status validate_pong_input(const PongInput &p_input) {
	// The input does not know the configured count: any seat a court can have.
	HAPTICS_RETURN_IF_ERROR(check_player("pong_input.local_player", p_input.local_player, true, PONG_MAX_PLAYERS));
	char name[64];
	for (int p = 0; p < PONG_MAX_PLAYERS; ++p) {
		const PongPlayerInput &player = p_input.players[p];
		std::snprintf(name, sizeof(name), "pong_input.players[%d].avatar", p);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, player.avatar, false, MAX_WORLD_M));
		std::snprintf(name, sizeof(name), "pong_input.players[%d].paddle_offset", p);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, player.paddle_offset, false, MAX_WORLD_M));
		std::snprintf(name, sizeof(name), "pong_input.players[%d].paddle_velocity", p);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, player.paddle_velocity, false, MAX_SPEED_M_PER_S));
		std::snprintf(name, sizeof(name), "pong_input.players[%d].normal", p);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, player.normal, true, 1e6));
		std::snprintf(name, sizeof(name), "pong_input.players[%d].pose_age_s", p);
		HAPTICS_RETURN_IF_ERROR(check_range(name, player.pose_age_s, 0.0, MAX_POSE_AGE_S));
	}
	return Status::success();
}

Status validate_pong_command(const PongCommand &p_command, const PongConfig &p_config) {
	switch (p_command.type) {
		case PongCommandType::SET_BALL:
		case PongCommandType::CORRECT_BALL: {
			const Vec3 &p = p_command.position;
			HAPTICS_RETURN_IF_ERROR(check_vector("pong_command.position", p, false, MAX_WORLD_M));
			const double w = court_half_x(p_config);
			const double l = court_half_z(p_config);
			if (std::abs(p.x) > w || std::abs(p.z) > l || p.y < 0.0 || p.y > p_config.wall_height_m) {
				return Status::error(StatusCode::OUT_OF_RANGE,
						"pong_command.position (%g, %g, %g) is outside the court (|x| <= %g, 0 <= y <= %g, |z| <= %g)",
						p.x, p.y, p.z, w, p_config.wall_height_m, l);
			}
			HAPTICS_RETURN_IF_ERROR(check_vector("pong_command.velocity", p_command.velocity, false, MAX_SPEED_M_PER_S));
			return check_vector("pong_command.spin", p_command.spin, false, MAX_SPIN_RAD_PER_S);
		}
		case PongCommandType::EFFECT:
			break;
		case PongCommandType::CLEAR_EFFECTS:
			return Status::success();
		default:
			return Status::error(StatusCode::INVALID_ARGUMENT, "pong_command.type: unknown type %d",
					static_cast<int>(p_command.type));
	}
	HAPTICS_RETURN_IF_ERROR(check_player("pong_command.player", p_command.player, false, p_config.players));
	const auto kind = static_cast<int>(p_command.kind);
	if (kind < 0 || kind >= PONG_EFFECT_KIND_COUNT) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "pong_command.kind: unknown kind %d", kind);
	}
	if (p_command.kind == PongEffectKind::RECOIL || p_command.kind == PongEffectKind::HIT) {
		HAPTICS_RETURN_IF_ERROR(check_vector("pong_command.direction", p_command.direction, true, 1e6));
	}
	if (!p_command.use_default_magnitude) {
		HAPTICS_RETURN_IF_ERROR(check_range("pong_command.magnitude_n", p_command.magnitude_n, 0.0, MAX_EFFECT_FORCE_N));
	}
	if (!p_command.use_default_duration) {
		HAPTICS_RETURN_IF_ERROR(
				check_range("pong_command.duration_s", p_command.duration_s, 1e-3, MAX_EFFECT_DURATION_S));
	}
	if (p_command.kind == PongEffectKind::REMOTE) {
		HAPTICS_RETURN_IF_ERROR(check_player("pong_command.owner", p_command.owner, false, p_config.players));
		if (p_command.owner == p_command.player) {
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"pong_command.owner must be another player (a remote paddle pulls toward an opponent's stylus)");
		}
	}
	return Status::success();
}

Status validate_pong_config(const PongConfig &p_config) {
	if (!valid_player_count(p_config.players)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"pong.players must be 2 (a rectangular court) or 4 (a square court); got %d", p_config.players);
	}
	const double r = p_config.ball_radius_m;
	const double top = p_config.wall_height_m - r;
	if (p_config.beginner_height_m < r || p_config.beginner_height_m > top) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"pong.beginner_height_m must keep the ball inside the court: in [%g, %g] for ball_radius_m %g and "
				"wall_height_m %g (got %g)",
				r, top, r, p_config.wall_height_m, p_config.beginner_height_m);
	}
	if (p_config.beginner_target_half_width_m > court_half_x(p_config)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"pong.beginner_target_half_width_m must fit the back wall: <= court_half_width_m %g (got %g)",
				court_half_x(p_config), p_config.beginner_target_half_width_m);
	}
	// Semi-implicit Euler resolves the contact spring while omega_n dt stays well below its
	// limit of 2; require omega_n <= the slowest servo rate, i.e. omega_n dt <= 1 at 250 Hz.
	const double omega = std::sqrt(p_config.ball_stiffness_n_per_m / p_config.ball_mass_kg);
	if (omega > MIN_RATE_HZ) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"pong.ball_stiffness_n_per_m %g on a %g kg ball rings at %g rad/s, faster than the slowest servo "
				"resolves (%g rad/s): lower it or make the ball heavier",
				p_config.ball_stiffness_n_per_m, p_config.ball_mass_kg, omega, MIN_RATE_HZ);
	}
	return Status::success();
}

} // namespace haptics
