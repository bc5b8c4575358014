#include "renderers/pong/pong_sim.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace haptics {

namespace {

bool is_finite(const HandSample &p_hand) {
	const Orientation &q = p_hand.orientation;
	return haptics::is_finite(p_hand.position_m) && haptics::is_finite(p_hand.velocity_m_per_s) &&
			std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

bool is_finite(const BallState &p_ball) {
	return haptics::is_finite(p_ball.position) && haptics::is_finite(p_ball.velocity) &&
			haptics::is_finite(p_ball.spin);
}

} // namespace

Vec3 rotate(const Orientation &p_q, const Vec3 &p_v) {
	// v' = v + w t + u x t with t = 2 u x v (u the vector part): q v q* without matrices.
	const Vec3 u{ p_q.x, p_q.y, p_q.z };
	const Vec3 t = cross(u, p_v) * 2.0;
	return p_v + t * p_q.w + cross(u, t);
}

PongSim::PongSim() {
	// Until the game says where its paddles are, none is in play: default poses (both at the
	// world origin) must neither touch the ball nor push the hand.
	input_ = default_pong_input();
	input_.local_player = -1;
	for (PongPlayerInput &player : input_.players) {
		player.active = false;
	}
	configure(PongConfig{});
	reset();
}

void PongSim::configure(const PongConfig &p_config) {
	const int before = config_.players;
	config_ = p_config;
	if (config_.players != before) {
		// Paddles that leave the court must not hold contacts; new ones start afresh.
		for (int p = 0; p < PONG_MAX_PLAYERS; ++p) {
			trackers_[p].reset();
			contacts_[p] = PaddleContact{};
		}
		territory_ = territory_of(ball_.position, config_.players);
	}
	law_ = make_paddle_law(p_config);
	effects_.configure(p_config);
}

void PongSim::clear_contacts() {
	for (int p = 0; p < players(); ++p) {
		trackers_[p].reset();
		contacts_[p] = PaddleContact{};
	}
	ball_force_ = Vec3{};
}

void PongSim::reset() {
	time_s_ = 0.0;
	input_time_s_ = 0.0;
	have_input_ = false;
	for (Vec3 &velocity : avatar_velocity_) {
		velocity = Vec3{};
	}
	ball_ = BallState{ { 0.0, config_.ball_radius_m, 0.0 }, {}, {} };
	correction_.clear();
	territory_ = territory_of(ball_.position, players());
	clear_contacts();
	effects_.clear();
	hand_ = HandForces{};
	paddle_contacts_ = 0;
	correction_step_max_m_ = 0.0;
	bounces_ = 0;
	events_.clear();
	events_.reset_dropped();
	pose_paddles(nullptr);
}

void PongSim::settle() {
	clear_contacts();
	effects_.clear();
	hand_ = HandForces{};
}

int PongSim::device_player() const {
	const int player = input_.local_player;
	return player >= 0 && player < players() && !input_.players[player].kinematic ? player : -1;
}

void PongSim::set_input(const PongInput &p_input) {
	const double elapsed = time_s_ - input_time_s_;
	for (int p = 0; p < players(); ++p) {
		if (!have_input_) {
			break;
		}
		if (elapsed <= 0.0) {
			continue; // Two inputs within one tick: keep the estimate.
		}
		const Vec3 velocity = (p_input.players[p].avatar - input_.players[p].avatar) / elapsed;
		avatar_velocity_[p] = length(velocity) <= PONG_MAX_AVATAR_SPEED_M_PER_S ? velocity : Vec3{};
	}
	input_ = p_input;
	for (PongPlayerInput &player : input_.players) {
		player.normal = normalized_or_zero(player.normal);
	}
	input_time_s_ = time_s_;
	have_input_ = true;
}

void PongSim::apply(const PongCommand &p_command) {
	switch (p_command.type) {
		case PongCommandType::SET_BALL:
			ball_.position = p_command.position;
			ball_.velocity = cap_length(p_command.velocity, config_.max_ball_speed_m_per_s);
			ball_.spin = cap_length(p_command.spin, config_.max_spin_rad_per_s);
			correction_.clear();
			territory_ = territory_of(ball_.position, players());
			clear_contacts();
			break;
		case PongCommandType::CORRECT_BALL: {
			const BallState target{ p_command.position, cap_length(p_command.velocity, config_.max_ball_speed_m_per_s),
				cap_length(p_command.spin, config_.max_spin_rad_per_s) };
			correction_.start(ball_, target, config_.correction_time_constant_s);
			territory_ = territory_of(target.position, players());
			// Contacts start afresh, as after a SET_BALL: a paddle's remembered side would push
			// the corrected ball back through it (a follower's ball ran off at twice the master's
			// speed, LAN divergence p99 0.5-2 m). Kept for the device player's paddle alone, the
			// same happened through the hand's own paddle. The force on a hand still touching
			// the ball is the same either way: the contact restarts on the side the ball is on.
			clear_contacts();
			break;
		}
		case PongCommandType::EFFECT:
			start_effect(p_command);
			break;
		case PongCommandType::CLEAR_EFFECTS:
			effects_.clear();
			break;
	}
}

void PongSim::start_effect(const PongCommand &p_command) {
	// Effects are rendered on the local device only; the game applies them to the motion of
	// the other players' paddles itself.
	if (p_command.kind == PongEffectKind::NONE || p_command.player != device_player()) {
		return;
	}
	EffectOrder order;
	order.kind = p_command.kind;
	order.direction = side_rotation_inverse(p_command.player, normalized_or_zero(p_command.direction));
	order.owner = p_command.owner;
	double magnitude = std::numeric_limits<double>::infinity();
	double duration = config_.mine_effect_duration_s;
	switch (p_command.kind) {
		case PongEffectKind::RECOIL:
			magnitude = config_.recoil_force_n;
			duration = config_.recoil_duration_s;
			break;
		case PongEffectKind::HIT:
			magnitude = config_.hit_force_n;
			duration = config_.hit_duration_s;
			break;
		case PongEffectKind::HEAVY:
			magnitude = config_.heavy_force_n;
			order.ramp_s = config_.mine_effect_ramp_s;
			break;
		case PongEffectKind::REMOTE:
			magnitude = config_.remote_max_force_n;
			order.ramp_s = config_.mine_effect_ramp_s;
			break;
		case PongEffectKind::SLOW:
			order.ramp_s = config_.mine_effect_ramp_s;
			break;
		case PongEffectKind::NONE:
			break;
	}
	order.magnitude_n = p_command.use_default_magnitude ? magnitude : p_command.magnitude_n;
	order.duration_s = p_command.use_default_duration ? duration : p_command.duration_s;
	effects_.start(order, hand_position_m_);
}

CorrectionCaps PongSim::correction_caps(int p_device, double p_dt_s) const {
	CorrectionCaps caps;
	caps.position_m = config_.correction_max_speed_m_per_s * p_dt_s;
	if (p_device < 0 || !poses_[p_device].touchable) {
		return caps;
	}
	// Near: within a tick of touching, its own flight and the correction's step included.
	const double r = config_.ball_radius_m;
	const double reach = config_.paddle_radius_m + r + (config_.max_ball_speed_m_per_s * p_dt_s + caps.position_m);
	if (length(ball_.position - poses_[p_device].center) > reach) {
		return caps;
	}
	const double budget = 0.5 * config_.correction_force_rate_n_per_s * p_dt_s; // Each half.
	const double per_metre = law_.hand_stiffness_n_per_m + law_.spin_force_gain * config_.max_spin_rad_per_s;
	if (per_metre > 0.0) {
		caps.position_m = std::min(caps.position_m, budget / per_metre);
	}
	caps.spin_rad_per_s = law_.spin_force_gain > 0.0 ? budget / (law_.spin_force_gain * r)
													 : std::numeric_limits<double>::infinity();
	caps.blend_velocity_and_spin = true;
	return caps;
}

void PongSim::pose_paddles(const HandSample *p_hand) {
	const double tau = std::clamp(time_s_ - input_time_s_, 0.0, PONG_MAX_EXTRAPOLATION_S);
	const double scale = config_.workspace_scale;
	const int device = device_player();
	for (int p = 0; p < players(); ++p) {
		const PongPlayerInput &in = input_.players[p];
		PaddlePose &pose = poses_[p];
		pose.touchable = in.active && !in.gun;
		pose.spin = in.spin;
		if (p != device || p_hand == nullptr) {
			const double ahead = std::clamp(in.pose_age_s, 0.0, PONG_MAX_POSE_EXTRAPOLATION_S) + tau;
			pose.center = in.avatar + in.paddle_offset + in.paddle_velocity * ahead;
			pose.velocity = in.paddle_velocity;
			pose.normal = in.normal;
			// The stylus as the input gave it (not moved on by tau: the remote target moves it on
			// over the whole age, network delay included).
			StylusSample &stylus = styluses_[p];
			stylus.position_m = side_rotation_inverse(p, in.paddle_offset / scale);
			stylus.velocity_m_per_s = side_rotation_inverse(p, (in.paddle_velocity - avatar_velocity_[p]) / scale);
			stylus.age_s = in.pose_age_s + std::max(time_s_ - input_time_s_, 0.0);
			continue;
		}
		if (!is_finite(*p_hand)) {
			pose.velocity = Vec3{}; // A glitched reading: hold the paddle where it was.
			continue;
		}
		const Vec3 avatar = in.avatar + avatar_velocity_[p] * tau;
		pose.center = avatar + side_rotation(p, p_hand->position_m * scale);
		pose.velocity = avatar_velocity_[p] + side_rotation(p, p_hand->velocity_m_per_s * scale);
		pose.normal = in.normal;
		if (p_hand->has_orientation) {
			const Vec3 facing = normalized_or_zero(rotate(p_hand->orientation, PADDLE_FACING_DEVICE));
			if (facing != Vec3{}) {
				pose.normal = side_rotation(p, facing);
			}
		}
		styluses_[p] = StylusSample{ p_hand->position_m, p_hand->velocity_m_per_s, 0.0 };
		hand_position_m_ = p_hand->position_m;
	}
}

void PongSim::emit(PongEventType p_type, const Vec3 &p_position, double p_speed, int p_player, CourtSurface p_wall) {
	PongEvent event;
	event.type = p_type;
	event.time_s = time_s_;
	event.position = p_position;
	event.speed = p_speed;
	event.territory = territory_of(p_position, players());
	event.back_wall_of = p_type == PongEventType::WALL ? back_wall_owner(p_wall, players()) : -1;
	event.player = p_player;
	event.wall = p_wall;
	events_.push(event);
}

void PongSim::step(double p_dt_s, const HandSample *p_hand) {
	time_s_ += p_dt_s;
	pose_paddles(p_hand);
	const int device = p_hand != nullptr ? device_player() : -1;
	const bool beginner = input_.beginner;
	if (correction_.active()) {
		// Before the contacts, so this tick's forces already see the corrected ball.
		const Vec3 velocity_before = ball_.velocity;
		const Vec3 step =
				correction_.advance(ball_, p_dt_s, config_.correction_time_constant_s, correction_caps(device, p_dt_s));
		// What the correction moved the ball this tick: its step, and the velocity it changed
		// flown for the tick (the ball would otherwise have flown on with the old one).
		const double moved = length(step + (ball_.velocity - velocity_before) * p_dt_s);
		correction_step_max_m_ = std::max(correction_step_max_m_, moved);
	}

	Vec3 ball_force;
	Vec3 spin_rate;
	bool in_contact = false;
	hand_.contact = Vec3{};
	hand_.spin = Vec3{};
	for (int p = 0; p < players(); ++p) {
		const PaddleContact &contact = contacts_[p] = trackers_[p].update(poses_[p], ball_, law_, p_dt_s);
		if (contact.started) {
			++paddle_contacts_;
			emit(PongEventType::PADDLE, ball_.position, contact.approach_speed_m_per_s, p);
		} else if (contact.released) {
			emit(PongEventType::RELEASE, ball_.position, length(ball_.velocity), p);
		}
		if (!contact.touching) {
			continue;
		}
		in_contact = true;
		ball_force += contact.ball_force_n;
		spin_rate += contact.spin_rate;
		if (p == device) {
			hand_.contact += side_rotation_inverse(p, contact.hand_contact_n);
			hand_.spin += side_rotation_inverse(p, contact.hand_spin_n);
		}
	}
	if (beginner) {
		ball_force.y = 0.0; // The ball stays in its plane whatever the paddle's tilt.
	}
	ball_force_ = ball_force;

	const BallState before = ball_;
	integrate_ball(ball_, ball_force, spin_rate, in_contact, beginner, config_, p_dt_s);
	if (!is_finite(ball_)) {
		ball_ = BallState{ before.position, {}, {} }; // Never let a NaN live on in the ball.
	}
	// An outgoing speed below what gravity adds in a tick cannot lift the ball off a surface:
	// it rests (or rolls) there instead of bouncing by micrometres.
	const double rest_speed = beginner ? 0.0 : config_.gravity_m_per_s2 * p_dt_s;
	const CourtHits hits = collide_with_court(ball_, config_, rest_speed);
	for (int h = 0; h < hits.count; ++h) {
		const CourtHit &hit = hits.hits[h];
		const bool floor = hit.surface == CourtSurface::FLOOR;
		if (hit.bounce.resting || (floor && hit.bounce.normal_speed < config_.min_bounce_speed_m_per_s)) {
			continue;
		}
		++bounces_;
		// While a correction glides in, the bounce belongs to the corrected ball: the one
		// following the master's trajectory, whose territory a floor hurt is charged to. At
		// the glide's position a new master's ball claimed a hurt in a territory 2.9 m from
		// the bounce everyone else saw, and the server refused it as a false claim.
		const Vec3 at = hit.position + along_surface(hit.surface, correction_.position_left());
		emit(floor ? PongEventType::FLOOR : PongEventType::WALL, at, hit.bounce.normal_speed, -1, hit.surface);
	}
	const Vec3 corrected = ball_.position + correction_.position_left();
	const int territory = territory_of(corrected, players());
	if (territory != territory_) {
		territory_ = territory;
		emit(PongEventType::TERRITORY, corrected, length(ball_.velocity));
	}

	// Effects keep time without a device too; only a device player feels them.
	const bool hand_ok = device >= 0 && is_finite(*p_hand);
	const Vec3 position = hand_ok ? p_hand->position_m : Vec3{};
	const Vec3 velocity = hand_ok ? p_hand->velocity_m_per_s : Vec3{};
	const Vec3 effects = effects_.advance(p_dt_s, position, velocity, styluses_);
	hand_.effects = hand_ok ? effects : Vec3{};
}

void PongSim::fill_state(PongState &r_state) const {
	r_state.time_s = time_s_;
	r_state.ball_position = ball_.position;
	r_state.ball_velocity = ball_.velocity;
	r_state.ball_spin = ball_.spin;
	r_state.ball_correction = correction_.position_left();
	r_state.ball_correction_step_max = correction_step_max_m_;
	r_state.territory = territory_;
	r_state.player_count = players();
	for (int p = 0; p < players(); ++p) {
		r_state.paddle_centers[p] = poses_[p].center;
		r_state.paddle_normals[p] = poses_[p].normal;
		r_state.paddle_velocities[p] = poses_[p].velocity;
		r_state.in_contact[p] = trackers_[p].touching();
	}
	r_state.hand_force = PongHandForce{};
	r_state.effects.count = static_cast<uint32_t>(effects_.list(r_state.effects.items.data()));
	r_state.paddle_contacts = paddle_contacts_;
	r_state.bounces = bounces_;
	r_state.events_dropped = events_.dropped();
	r_state.remote_work_j = effects_.remote_work_j();
}

} // namespace haptics
