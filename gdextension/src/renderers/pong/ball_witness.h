#pragma once

// The server's check of a master's ball (issue 36: a master that streamed a forged ball took
// points at will). Every state of the master's stream is checked against this machine's own
// simulation of the ball, the servo's ball laws (ball.h), flown from the start of the ball's
// current flight (by the master's servo time, so the path's delay and jitter do not enter):
//   flown        free flight and court bounces from the flight's start lead to it, within
//                WITNESS_POSITION_M and WITNESS_VELOCITY_M_PER_S (the same laws in the same
//                steps: an honest master's ball, a correction gliding in included, is there to
//                a micrometre); the floor bounces since the previous state are ones this
//                machine saw, reported for the floor claims. A flown state WITNESS_FLIGHT_S
//                after the flight's start starts the next (so a long flight is not flown anew
//                for every state, and the tolerance cannot be spent again and again to bend
//                the ball, as checking each state from the one before it would let it);
//   struck       not, but some paddle was within its radius, the ball's and WITNESS_REACH_M
//                of the flight since the previous state: a pose the master sent of its own
//                paddle within WITNESS_POSE_WINDOW_S (its clock is the states'), or any paddle
//                as this servo had it within WITNESS_WINDOW_S of the time the flight passed
//                there (the state placed in this servo's time by its age; its reach grows by
//                how far the master's copy of it may have been carried on by its velocity,
//                PONG_MAX_POSE_EXTRAPOLATION_S); and the state lies
//                within what the ball can fly at max_ball_speed from there: a new flight;
//   unreachable  neither, or a second state of a moment already kept that is not the same:
//                the state is refused and not kept;
//   anchor       the first of an epoch (the server gives it the ball it handed over, placed
//                in the master's time by the first state's age: the new master's own states
//                are then checked from there), the first after WITNESS_MAX_GAP_S in which
//                the master sent nothing if it lies in or near the master's own territory
//                (else old: a forger's way in), or within WITNESS_SETTLE_S of the epoch's first a
//                state neither flown nor struck that lies in the master's own territory or
//                within WITNESS_SETTLE_MARGIN_M of it (one whose vertical velocity turned up
//                against a falling flight, in the master's own territory, is reported as a
//                floor bounce there: the corrected ball it streams is lifted by what is left
//                to blend in, and never reaches the floor itself):
//                taken as it is, a flight's start;
//   old          no state of its epoch before it, a copy of one kept, or one back from a
//                silence far from the master's territory: not judged, not played.
// Game thread only; the paddle history is fed once a frame (note_paddles).

#include "core/base/vec3.h"
#include "renderers/pong/ball.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_messages.gen.h"
#include "renderers/pong/pong_state.gen.h"

#include <array>
#include <cstddef>

namespace haptics {

// The servo's period: the master's ball moves in such steps.
inline constexpr double WITNESS_STEP_S = 0.001;
// What an honest master's stream may differ from free flight by: the wire's 32-bit floats,
// and a court bounce of the ball while a correction glides in (ball_correction.h), which
// bounces the ball, not the corrected one.
inline constexpr double WITNESS_POSITION_M = 0.10;
inline constexpr double WITNESS_VELOCITY_M_PER_S = 0.5;
// How long one flight is flown before a state on it starts the next: a new master's stream
// while a correction glides in near its paddle carries the ball's velocity without the part
// still to blend in (ball_correction.h), and a flight started there misses by that part
// times the flight's length (0.24 m/s measured on the rough path: 10 cm after 0.4 s).
inline constexpr double WITNESS_FLIGHT_S = 0.2;
// How near a paddle's centre the ball must pass, beyond the two radii, to count as struck:
// our copy of a remote paddle is its pose carried on by its velocity.
inline constexpr double WITNESS_REACH_M = 0.25;
// How far apart in time a paddle sample and the flight may be: the state's age is an estimate
// (each leg taken as half the round trip) and our paddles were posed a leg late.
inline constexpr double WITNESS_WINDOW_S = 0.5;
// The same for the master's own poses, which carry its clock: a loss burst of poses, and a
// contact's length.
inline constexpr double WITNESS_POSE_WINDOW_S = 0.12;
// The master's poses kept: two seconds at 125 Hz.
inline constexpr size_t WITNESS_POSES = 256;
// How long after an epoch's first state the new master's ball may still be settling: a
// hand-off's correction glides into it, blended more slowly near its paddle (ball_correction.h),
// so its stream need not fly freely yet. An unexplained state then starts the flight anew,
// in or near the master's own territory only.
inline constexpr double WITNESS_SETTLE_S = PONG_WITNESS_SETTLE_S;
inline constexpr double WITNESS_SETTLE_MARGIN_M = 1.0;
// States kept per epoch to check later ones (and reordered ones) from: a second of a stream
// at its fastest (125 Hz), so a flight's start is always among them.
inline constexpr size_t WITNESS_STATES = 128;
// Paddle samples kept, one a frame: several seconds at 60-125 Hz.
inline constexpr size_t WITNESS_PADDLE_SAMPLES = 512;
// A master silent longer than this starts afresh: its heartbeat has then been silent for most
// of the 3 s after which the computer takes its seat.
inline constexpr double WITNESS_MAX_GAP_S = 2.0;

class BallWitness {
public:
	// A new match: no states, no paddles.
	void reset();
	// The servo's state after a frame (this machine's servo time, every seat's paddle).
	void note_paddles(const PongState &p_state);
	// A pose of a paddle the master drives, in the master's clock.
	void note_pose(const PongWitnessPose &p_pose);
	// Checks p_check, at this servo's time p_now_s, in a court of p_config (p_beginner: the
	// ball holds its height), and keeps it unless refused.
	PongWitnessVerdict check(const PongWitnessCheck &p_check, double p_now_s, const PongConfig &p_config,
			bool p_beginner);

private:
	struct Kept {
		double time_s = 0.0; // The master's servo time.
		BallState ball;
		bool starts_flight = true;
	};
	struct PaddleSample {
		double time_s = 0.0; // This servo's time.
		int players = 0;
		std::array<Vec3, PONG_MAX_PLAYERS> centers{};
		std::array<double, PONG_MAX_PLAYERS> speeds{};
	};

	// The kept state latest before p_time_s (p_flight_start: that starts a flight), or null.
	const Kept *before(double p_time_s, bool p_flight_start) const;
	void keep(const Kept &p_state);
	// Whether a paddle was near p_ball's centre at this servo's time p_time_s, or one of the
	// master's at its time p_master_time_s.
	bool paddle_near(const Vec3 &p_ball, double p_time_s, double p_master_time_s, double p_reach_m) const;

	int epoch_ = -1;
	double latest_seen_s_ = -1.0; // The newest state of the epoch checked, kept or not.
	std::array<Kept, WITNESS_STATES> kept_{};
	size_t kept_count_ = 0; // Sorted by time, oldest first.
	std::array<PaddleSample, WITNESS_PADDLE_SAMPLES> paddles_{};
	size_t paddle_next_ = 0;
	size_t paddle_count_ = 0;
	std::array<PongWitnessPose, WITNESS_POSES> poses_{};
	size_t pose_next_ = 0;
	size_t pose_count_ = 0;
	double epoch_start_s_ = 0.0; // The master's time of the epoch's first state kept.
};

} // namespace haptics
