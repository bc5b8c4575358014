#pragma once

// Haptic Battle Pong's simulation, stepped at the servo period: the paddles' poses from the
// game's input and the local device, the ball-paddle contact law (paddle_contact.h), the
// ball's flight and court bounces (ball.h), the effects on the device player's hand
// (hand_effects.h), and the events of each step (pong_event_ring.h). Engine-free, single
// threaded (whoever ticks the servo), no allocation, no locks, no logs.
//
// The paddles, each tick (tau = time since the latest input, at most
// PONG_MAX_EXTRAPOLATION_S, so a stalled game freezes its paddles within a few frames):
//   device paddle (local_player, not kinematic):
//     centre   = avatar + v_avatar tau + side_rotation(player, device position * scale)
//     velocity = v_avatar + side_rotation(player, device velocity * scale)
//     normal   = side_rotation(player, orientation * PADDLE_FACING_DEVICE) with an
//                orientation, else the input's normal
//   every other paddle (game-driven; age = the input's pose_age_s, at most
//   PONG_MAX_POSE_EXTRAPOLATION_S: a remote player's pose is that old when it is handed over):
//     centre   = avatar + paddle_offset + paddle_velocity (age + tau),  velocity = paddle_velocity
// Each player's stylus (REMOTE's owner, hand_effects.h) in its device frame: the device's
// reading for the device player (age 0); for the others paddle_offset / scale with velocity
// (paddle_velocity - v_avatar) / scale, aged input.pose_age_s + tau (the network's delay of a
// remote player's sample plus the time since the input).
// v_avatar is estimated from successive inputs: the game moves the avatar at frame rate, and
// without it the paddle would jump a few centimetres every frame while the avatar walks,
// which the hand would feel as a force step. A jump faster than PONG_MAX_AVATAR_SPEED is a
// teleport, not a walk, and is not extrapolated.
//
// Only the first PongConfig::players paddles exist; the input's other entries are ignored.
// Then, per step: contacts (every paddle), the ball's forces and spin rate (beginner mode
// drops the vertical part of the paddles' push), semi-implicit Euler, court bounces, the
// territory. Events: FLOOR (normal speed >= min_bounce_speed), WALL (any bounce that is not
// the ball coming to rest), PADDLE and RELEASE, TERRITORY. A SET_BALL moves the ball without
// events (a serve is not play) and starts contacts afresh. A CORRECT_BALL (a network
// correction) is blended in over the next ticks, before each tick's contacts, with the
// ball's physics running on (ball_correction.h); contacts start afresh as after a SET_BALL;
// the territory is the corrected ball's (the ball plus what is still to blend in), taken
// without an event when the correction arrives.

#include "core/base/vec3.h"
#include "core/device/device.h"
#include "renderers/pong/ball.h"
#include "renderers/pong/ball_correction.h"
#include "renderers/pong/hand_effects.h"
#include "renderers/pong/paddle_contact.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_event_ring.h"
#include "renderers/pong/pong_input.h"
#include "renderers/pong/pong_output.h"

#include <cstdint>

namespace haptics {

// Faster avatar moves between two inputs are teleports (a reset): not extrapolated.
inline constexpr double PONG_MAX_AVATAR_SPEED_M_PER_S = 10.0;

// The local device this tick, device space.
struct HandSample {
	Vec3 position_m;
	Vec3 velocity_m_per_s;
	Orientation orientation;
	bool has_orientation = false;
};

// The device player's hand forces of the latest step, device space, N.
struct HandForces {
	Vec3 contact;
	Vec3 spin;
	Vec3 effects;
};

// p_v rotated by the unit quaternion p_q.
Vec3 rotate(const Orientation &p_q, const Vec3 &p_v);

class PongSim {
public:
	// No paddle in play and no device player until the first set_input().
	PongSim();

	void configure(const PongConfig &p_config);
	// A new session: time 0, the ball at rest on the centre spot, contacts, effects, events
	// and counters cleared. The input is kept.
	void reset();
	// Becoming the active renderer: contacts and effects start afresh, the ball is kept.
	void settle();
	// Both validated (pong_validation.h).
	void set_input(const PongInput &p_input);
	void apply(const PongCommand &p_command);
	// One step of p_dt_s. p_hand: the local device, or null when there is none.
	void step(double p_dt_s, const HandSample *p_hand);

	// The player whose hand the device moves (-1: none).
	int device_player() const;
	double time_s() const { return time_s_; }
	const BallState &ball() const { return ball_; }
	const BallCorrection &correction() const { return correction_; }
	int territory() const { return territory_; }
	const PaddlePose &paddle(int p_player) const { return poses_[p_player]; }
	const PaddleContact &contact(int p_player) const { return contacts_[p_player]; }
	Vec3 ball_contact_force() const { return ball_force_; } // The paddles' push, world, N.
	const HandForces &hand_forces() const { return hand_; }
	const HandEffects &effects() const { return effects_; }
	const PongConfig &config() const { return config_; }
	const PongInput &input() const { return input_; }
	int player_count() const { return config_.players; }
	// The state for the game, hand_force left zero (the renderer knows the scaled forces).
	void fill_state(PongState &r_state) const;
	PongEventRing &events() { return events_; }

private:
	void pose_paddles(const HandSample *p_hand);
	void start_effect(const PongCommand &p_command);
	// What a correction may take this tick, p_device the device player this tick (-1: none).
	CorrectionCaps correction_caps(int p_device, double p_dt_s) const;
	void emit(PongEventType p_type, const Vec3 &p_position, double p_speed, int p_player = -1,
			CourtSurface p_wall = CourtSurface::FLOOR);
	int players() const { return config_.players; }
	void clear_contacts();

	PongConfig config_;
	PaddleLaw law_;
	PongInput input_;
	double input_time_s_ = 0.0;
	bool have_input_ = false;
	Vec3 avatar_velocity_[PONG_MAX_PLAYERS];

	double time_s_ = 0.0;
	BallState ball_;
	BallCorrection correction_;
	int territory_ = 0;
	PaddleContactTracker trackers_[PONG_MAX_PLAYERS];
	PaddlePose poses_[PONG_MAX_PLAYERS];
	PaddleContact contacts_[PONG_MAX_PLAYERS];
	StylusSample styluses_[PONG_MAX_PLAYERS]; // Each player's stylus in its own device frame.
	Vec3 ball_force_;

	HandEffects effects_;
	HandForces hand_;
	Vec3 hand_position_m_; // The latest device position (an effect starts from it).

	uint64_t paddle_contacts_ = 0;
	double correction_step_max_m_ = 0.0;
	uint64_t bounces_ = 0;
	PongEventRing events_;
};

} // namespace haptics
