#include "renderers/pong/pong_validation.h"

#include "core/base/value_checks.h"
#include "core/servo/servo_rate.h"
#include "core/wire/codec.h"

#include <cmath>
#include <cstdio>

namespace haptics {

namespace {

// A player of a court of p_players (0..p_players - 1).
Status check_player(const char *p_name, int32_t p_player, int p_players) {
	if (p_player >= 0 && p_player < p_players) {
		return Status::success();
	}
	return Status::error(StatusCode::OUT_OF_RANGE, "%s must be 0..%d on this court (got %d)", p_name, p_players - 1,
			p_player);
}

} // namespace

Status validate_pong_input(const PongInput &p_input) {
	return check_fields(p_input);
}

Status validate_pong_command(const PongCommand &p_command, const PongConfig &p_config) {
	HAPTICS_RETURN_IF_ERROR(check_fields(p_command));
	switch (p_command.type) {
		case PongCommandType::SET_BALL:
		case PongCommandType::CORRECT_BALL: {
			const Vec3 &p = p_command.position;
			const double w = court_half_x(p_config);
			const double l = court_half_z(p_config);
			if (std::abs(p.x) > w || std::abs(p.z) > l || p.y < 0.0 || p.y > p_config.wall_height_m) {
				return Status::error(StatusCode::OUT_OF_RANGE,
						"PongCommand.position (%g, %g, %g) is outside the court (|x| <= %g, 0 <= y <= %g, |z| <= %g)",
						p.x, p.y, p.z, w, p_config.wall_height_m, l);
			}
			return Status::success();
		}
		case PongCommandType::EFFECT:
			break;
		case PongCommandType::CLEAR_EFFECTS:
			return Status::success();
	}
	HAPTICS_RETURN_IF_ERROR(check_player("PongCommand.player", p_command.player, p_config.players));
	if (p_command.kind == PongEffectKind::RECOIL || p_command.kind == PongEffectKind::HIT) {
		HAPTICS_RETURN_IF_ERROR(check_vector("PongCommand.direction", p_command.direction, true, 1e6));
	}
	if (!p_command.use_default_duration && !(p_command.duration_s > 0.0)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "PongCommand.duration_s must be above 0 (got %g)",
				p_command.duration_s);
	}
	if (p_command.kind == PongEffectKind::REMOTE) {
		HAPTICS_RETURN_IF_ERROR(check_player("PongCommand.owner", p_command.owner, p_config.players));
		if (p_command.owner == p_command.player) {
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"PongCommand.owner must be another player (a remote paddle pulls toward an opponent's stylus)");
		}
	}
	return Status::success();
}

Status validate_pong_config(const PongConfig &p_config) {
	if (!valid_player_count(p_config.players)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"PongSettings.players must be 2 (a rectangular court) or 4 (a square court); got %d", p_config.players);
	}
	const double r = p_config.ball_radius_m;
	const double top = p_config.wall_height_m - r;
	if (p_config.beginner_height_m < r || p_config.beginner_height_m > top) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"PongSettings.beginner_height_m must keep the ball inside the court: in [%g, %g] for ball_radius_m %g and "
				"wall_height_m %g (got %g)",
				r, top, r, p_config.wall_height_m, p_config.beginner_height_m);
	}
	if (p_config.beginner_target_half_width_m > court_half_x(p_config)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"PongSettings.beginner_target_half_width_m must fit the back wall: <= court_half_width_m %g (got %g)",
				court_half_x(p_config), p_config.beginner_target_half_width_m);
	}
	// Semi-implicit Euler resolves the contact spring while omega_n dt stays well below its
	// limit of 2; require omega_n <= the slowest servo rate, i.e. omega_n dt <= 1 at 250 Hz.
	const double omega = std::sqrt(p_config.ball_stiffness_n_per_m / p_config.ball_mass_kg);
	if (omega > MIN_RATE_HZ) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"PongSettings.ball_stiffness_n_per_m %g on a %g kg ball rings at %g rad/s, faster than the slowest servo "
				"resolves (%g rad/s): lower it or make the ball heavier",
				p_config.ball_stiffness_n_per_m, p_config.ball_mass_kg, omega, MIN_RATE_HZ);
	}
	return Status::success();
}

} // namespace haptics
