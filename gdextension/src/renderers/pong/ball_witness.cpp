#include "renderers/pong/ball_witness.h"

#include "renderers/pong/court.h"
#include "renderers/pong/pong_input.h"

#include <algorithm>
#include <cmath>

namespace haptics {

namespace {

// The flight is compared with the paddles every few steps: a paddle's disc is 0.44 m across,
// and the ball flies at most 45 mm in five steps.
constexpr int PADDLE_CHECK_STEPS = 5;

// Whether p_position lies in p_territory or within WITNESS_SETTLE_MARGIN_M of it: a hand-off
// happens at the border, and the new master's corrected ball may still be across it.
bool near_territory(const Vec3 &p_position, int p_territory, int p_players) {
	const double m = WITNESS_SETTLE_MARGIN_M;
	const Vec3 around[] = { p_position, p_position + Vec3{ m, 0.0, 0.0 }, p_position - Vec3{ m, 0.0, 0.0 },
		p_position + Vec3{ 0.0, 0.0, m }, p_position - Vec3{ 0.0, 0.0, m } };
	for (const Vec3 &point : around) {
		if (territory_of(point, p_players) == p_territory) {
			return true;
		}
	}
	return false;
}

} // namespace

void BallWitness::reset() {
	epoch_ = -1;
	latest_seen_s_ = -1.0;
	kept_count_ = 0;
	paddle_next_ = 0;
	paddle_count_ = 0;
	pose_next_ = 0;
	pose_count_ = 0;
}

void BallWitness::note_pose(const PongWitnessPose &p_pose) {
	poses_[pose_next_] = p_pose;
	pose_next_ = (pose_next_ + 1) % WITNESS_POSES;
	pose_count_ = std::min(pose_count_ + 1, WITNESS_POSES);
}

void BallWitness::note_paddles(const PongState &p_state) {
	if (paddle_count_ > 0) {
		const size_t last = (paddle_next_ + WITNESS_PADDLE_SAMPLES - 1) % WITNESS_PADDLE_SAMPLES;
		if (p_state.time_s < paddles_[last].time_s) {
			reset(); // The servo's clock started over: a new match.
		}
	}
	PaddleSample &sample = paddles_[paddle_next_];
	sample.time_s = p_state.time_s;
	sample.players = std::clamp(int(p_state.player_count), 0, PONG_MAX_PLAYERS);
	for (int p = 0; p < sample.players; ++p) {
		sample.centers[p] = p_state.paddle_centers[p];
		sample.speeds[p] = length(p_state.paddle_velocities[p]);
	}
	paddle_next_ = (paddle_next_ + 1) % WITNESS_PADDLE_SAMPLES;
	paddle_count_ = std::min(paddle_count_ + 1, WITNESS_PADDLE_SAMPLES);
}

const BallWitness::Kept *BallWitness::before(double p_time_s, bool p_flight_start) const {
	const Kept *latest = nullptr;
	for (size_t i = 0; i < kept_count_ && kept_[i].time_s < p_time_s; ++i) {
		if (!p_flight_start || kept_[i].starts_flight) {
			latest = &kept_[i];
		}
	}
	return latest;
}

void BallWitness::keep(const Kept &p_state) {
	size_t at = kept_count_;
	while (at > 0 && kept_[at - 1].time_s > p_state.time_s) {
		--at;
	}
	if (kept_count_ == WITNESS_STATES) {
		if (at == 0) {
			return; // Older than every state kept: nothing later is checked from it.
		}
		std::move(kept_.begin() + 1, kept_.begin() + at, kept_.begin());
		--at;
		--kept_count_;
	}
	std::move_backward(kept_.begin() + at, kept_.begin() + kept_count_, kept_.begin() + kept_count_ + 1);
	kept_[at] = p_state;
	++kept_count_;
}

bool BallWitness::paddle_near(const Vec3 &p_ball, double p_time_s, double p_master_time_s, double p_reach_m) const {
	const double reach_squared = p_reach_m * p_reach_m;
	for (size_t i = 0; i < pose_count_; ++i) {
		const PongWitnessPose &pose = poses_[i];
		if (pose.epoch == epoch_ && std::abs(pose.time_s - p_master_time_s) <= WITNESS_POSE_WINDOW_S &&
				length_squared(pose.center - p_ball) <= reach_squared) {
			return true;
		}
	}
	for (size_t i = 0; i < paddle_count_; ++i) {
		const PaddleSample &sample = paddles_[i];
		if (std::abs(sample.time_s - p_time_s) > WITNESS_WINDOW_S) {
			continue;
		}
		for (int p = 0; p < sample.players; ++p) {
			const double reach = p_reach_m + sample.speeds[p] * PONG_MAX_POSE_EXTRAPOLATION_S;
			if (length_squared(sample.centers[p] - p_ball) <= reach * reach) {
				return true;
			}
		}
	}
	return false;
}

PongWitnessVerdict BallWitness::check(const PongWitnessCheck &p_check, double p_now_s, const PongConfig &p_config,
		bool p_beginner) {
	PongWitnessVerdict verdict;
	if (p_check.new_match) {
		epoch_ = -1;
	}
	Kept state{ p_check.time_s, BallState{ p_check.position, p_check.velocity, p_check.spin }, true };
	if (p_check.epoch < epoch_) {
		verdict.verdict = WitnessVerdict::OLD;
		return verdict;
	}
	if (p_check.epoch > epoch_) {
		epoch_ = static_cast<int>(p_check.epoch);
		kept_count_ = 0;
		latest_seen_s_ = -1.0;
	}
	const Kept *previous = before(p_check.time_s, false);
	const Kept *from = before(p_check.time_s, true);
	const double seen = std::max(latest_seen_s_, previous ? previous->time_s : -1.0);
	const bool after_gap = previous != nullptr && p_check.time_s - seen > WITNESS_MAX_GAP_S;
	if (after_gap && !near_territory(p_check.position, p_check.territory, p_config.players)) {
		// Back from a silence with the ball far from its own territory: nothing to check it
		// from, and no anchor (a forger's way in); an honest master's hand-off is on its way.
		verdict.verdict = WitnessVerdict::OLD;
		return verdict;
	}
	latest_seen_s_ = std::max(latest_seen_s_, p_check.time_s);
	if (kept_count_ == 0 || after_gap) {
		if (kept_count_ == 0) {
			epoch_start_s_ = p_check.time_s;
		}
		keep(state);
		verdict.verdict = WitnessVerdict::ANCHOR;
		return verdict;
	}
	for (size_t i = 0; i < kept_count_; ++i) {
		if (kept_[i].time_s == p_check.time_s) {
			// A second state of one moment: a copy, or a contradiction.
			verdict.miss_m = length(kept_[i].ball.position - p_check.position);
			verdict.miss_m_per_s = length(kept_[i].ball.velocity - p_check.velocity);
			const bool copy = verdict.miss_m <= WITNESS_POSITION_M && verdict.miss_m_per_s <= WITNESS_VELOCITY_M_PER_S;
			verdict.verdict = copy ? WitnessVerdict::OLD : WitnessVerdict::UNREACHABLE;
			return verdict;
		}
	}
	if (from == nullptr) {
		verdict.verdict = WitnessVerdict::OLD;
		return verdict;
	}
	const double flight = p_check.time_s - from->time_s;
	verdict.gap_s = p_check.time_s - previous->time_s;
	verdict.allowed_m = WITNESS_POSITION_M;

	// Where the state was in this servo's time: it arrived p_check.age_s after it was sent.
	const double sent_here = p_now_s - p_check.age_s;
	const double reach = p_config.paddle_radius_m + p_config.ball_radius_m + WITNESS_REACH_M;
	const double rest_speed = p_beginner ? 0.0 : p_config.gravity_m_per_s2 * WITNESS_STEP_S;
	// Only the part after the previous state is news: its bounces, a paddle near it.
	const double news_from = previous->time_s - from->time_s;
	BallState ball = from->ball;
	double t = 0.0; // Since the flight's start.
	bool struck = false;
	Vec3 struck_at;
	double struck_t = 0.0;
	for (int step = 1; t < flight - 1e-9; ++step) {
		const double dt = std::min(WITNESS_STEP_S, flight - t);
		t += dt;
		integrate_ball(ball, Vec3{}, Vec3{}, false, p_beginner, p_config, dt);
		const CourtHits hits = collide_with_court(ball, p_config, rest_speed);
		const bool news = t > news_from;
		for (int h = 0; h < hits.count && news && !struck; ++h) {
			const CourtHit &hit = hits.hits[h];
			const bool bounce = hit.surface == CourtSurface::FLOOR && !hit.bounce.resting &&
					hit.bounce.normal_speed >= p_config.min_bounce_speed_m_per_s;
			if (bounce && verdict.bounces.size() < size_t(PONG_WITNESS_MAX_BOUNCES)) {
				verdict.bounces.push_back({ hit.position, p_check.age_s + (flight - t) });
			}
		}
		const bool compare = step % PADDLE_CHECK_STEPS == 0 || t >= flight - 1e-9;
		if (news && !struck && compare && paddle_near(ball.position, sent_here - (flight - t), from->time_s + t, reach)) {
			struck = true;
			struck_at = ball.position;
			struck_t = t;
		}
	}
	verdict.miss_m = length(ball.position - p_check.position);
	verdict.miss_m_per_s = length(ball.velocity - p_check.velocity);
	const bool flown = verdict.miss_m <= verdict.allowed_m && verdict.miss_m_per_s <= WITNESS_VELOCITY_M_PER_S;
	// From a paddle's touch the ball flies at most max_ball_speed (the paddle's push included).
	const bool reachable = struck &&
			length(p_check.position - struck_at) <= p_config.max_ball_speed_m_per_s * (flight - struck_t) + reach;
	if (flown) {
		verdict.verdict = WitnessVerdict::FLOWN;
		state.starts_flight = flight >= WITNESS_FLIGHT_S;
	} else if (reachable) {
		verdict.verdict = WitnessVerdict::STRUCK;
	} else if (p_check.time_s - epoch_start_s_ <= WITNESS_SETTLE_S &&
			near_territory(p_check.position, p_check.territory, p_config.players)) {
		verdict.verdict = WitnessVerdict::ANCHOR;
		verdict.bounces.clear();
		// A settling ball's floor bounce shows in its stream as its vertical velocity turning
		// up in mid-air: the master's ball bounced, the corrected ball it streams is lifted by
		// what is left to blend in. Counted in the master's own territory only.
		const bool turned_up = -ball.velocity.y >= p_config.min_bounce_speed_m_per_s && p_check.velocity.y > 0.0;
		if (turned_up && territory_of(p_check.position, p_config.players) == p_check.territory) {
			const Vec3 floor{ p_check.position.x, p_config.ball_radius_m, p_check.position.z };
			verdict.bounces.push_back({ floor, p_check.age_s });
		}
	} else {
		verdict.verdict = WitnessVerdict::UNREACHABLE;
		verdict.bounces.clear();
		return verdict;
	}
	keep(state);
	return verdict;
}

} // namespace haptics
