// The effects on the device player's hand (renderers/pong/hand_effects.h) through the simulation:
// directions and magnitudes in device space for both sides, the laws of slow, heavy and
// remote, the remote's mirror, cap and low-pass, and the ramps' timing.

#include "pong/pong_test_support.h"

#include "renderers/pong/hand_effects.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace haptics;
using namespace haptics::test;

namespace {

// A sim whose device player is p_player, its ball parked out of every paddle's reach.
PongSim device_sim(int p_player, PongInput *r_input = nullptr) {
	PongSim sim;
	PongInput input = idle_input();
	input.local_player = p_player;
	input.players[p_player].kinematic = false;
	input.players[p_player].avatar = { 0.0, 1.0, p_player == 0 ? 2.0 : -2.0 };
	sim.set_input(input);
	sim.apply(set_ball({ 1.0, 0.07, 0.0 }));
	if (r_input) {
		*r_input = input;
	}
	return sim;
}

PongCommand effect(int p_player, PongEffectKind p_kind, const Vec3 &p_direction = {}) {
	PongCommand command;
	command.type = PongCommandType::EFFECT;
	command.player = p_player;
	command.kind = p_kind;
	command.direction = p_direction;
	command.owner = 1 - p_player;
	return command;
}

// Steps p_seconds with the hand at p_hand; returns the last effects force.
Vec3 run(PongSim &r_sim, double p_seconds, const HandSample &p_hand) {
	const int ticks = static_cast<int>(std::lround(p_seconds / PONG_DT));
	for (int k = 0; k < ticks; ++k) {
		r_sim.step(PONG_DT, &p_hand);
	}
	return r_sim.hand_forces().effects;
}

} // namespace

TEST_CASE("pong effects: recoil and hit push along their world direction, turned into each player's device space") {
	const PongConfig config;
	const Vec3 world{ 0.6, 0.0, -0.8 }; // Unit.
	for (int player = 0; player < 2; ++player) {
		CAPTURE(player);
		// Player 1 faces the other way: world x and z are its device -x and -z.
		const Vec3 device = player == 0 ? world : Vec3{ -0.6, 0.0, 0.8 };
		PongSim sim = device_sim(player);
		const HandSample hand;
		sim.apply(effect(player, PongEffectKind::RECOIL, world * 3.0)); // Any length: normalised.
		sim.step(PONG_DT, &hand);
		const Vec3 recoil = sim.hand_forces().effects;
		CHECK(recoil.x == doctest::Approx(device.x * config.recoil_force_n));
		CHECK(recoil.y == doctest::Approx(0.0));
		CHECK(recoil.z == doctest::Approx(device.z * config.recoil_force_n));
		// Held for recoil_duration_s, then gone.
		CHECK(length(run(sim, config.recoil_duration_s - 0.002, hand)) == doctest::Approx(config.recoil_force_n));
		CHECK(run(sim, 0.003, hand) == Vec3{});

		PongCommand hit = effect(player, PongEffectKind::HIT, world);
		hit.magnitude_n = 2.0;
		hit.use_default_magnitude = false;
		sim.apply(hit);
		sim.step(PONG_DT, &hand);
		CHECK(sim.hand_forces().effects.x == doctest::Approx(device.x * 2.0));
		CHECK(sim.hand_forces().effects.z == doctest::Approx(device.z * 2.0));
		CHECK(length(run(sim, config.hit_duration_s - 0.002, hand)) == doctest::Approx(2.0));
		CHECK(run(sim, 0.003, hand) == Vec3{});
	}
}

TEST_CASE("pong effects: an effect for a player the device does not move is not felt here") {
	PongSim sim = device_sim(0);
	const HandSample hand;
	sim.apply(effect(1, PongEffectKind::HEAVY));
	CHECK(run(sim, 1.0, hand) == Vec3{});
	CHECK_FALSE(sim.effects().running(PongEffectKind::HEAVY));
}

TEST_CASE("pong effects: slow is -b v on the device velocity, heavy a constant down, both ramped in and out on time") {
	const PongConfig config;
	const double ramp = config.mine_effect_ramp_s;
	const double duration = config.mine_effect_duration_s;
	for (int player = 0; player < 2; ++player) {
		CAPTURE(player);
		PongSim sim = device_sim(player);
		HandSample hand;
		hand.velocity_m_per_s = { 0.1, -0.05, 0.2 };
		sim.apply(effect(player, PongEffectKind::SLOW));
		sim.apply(effect(player, PongEffectKind::HEAVY));
		const Vec3 full = hand.velocity_m_per_s * -config.slow_damping_n_s_per_m + Vec3{ 0.0, -config.heavy_force_n, 0.0 };
		sim.step(PONG_DT, &hand);
		CHECK(sim.hand_forces().effects == Vec3{}); // The ramp starts from zero: no kick.
		// Half way up the ramp: half the force (the k-th tick renders elapsed (k - 1) dt).
		Vec3 force = run(sim, 0.5 * ramp, hand);
		CHECK(force.x == doctest::Approx(0.5 * full.x));
		CHECK(force.y == doctest::Approx(0.5 * full.y));
		force = run(sim, 0.5 * ramp, hand);
		CHECK(force.x == doctest::Approx(full.x));
		CHECK(force.y == doctest::Approx(full.y));
		CHECK(force.z == doctest::Approx(full.z));
		// Half way down the final ramp.
		force = run(sim, duration - 1.5 * ramp, hand);
		CHECK(force.y == doctest::Approx(0.5 * full.y));
		CHECK(run(sim, 0.5 * ramp + PONG_DT, hand) == Vec3{});
		CHECK_FALSE(sim.effects().running(PongEffectKind::SLOW));
	}
	CHECK(effect_gain(0.0, 4.0, 0.25) == 0.0);
	CHECK(effect_gain(0.1, 4.0, 0.25) == doctest::Approx(0.4));
	CHECK(effect_gain(2.0, 4.0, 0.25) == 1.0);
	CHECK(effect_gain(3.9, 4.0, 0.25) == doctest::Approx(0.4));
	CHECK(effect_gain(4.0, 4.0, 0.25) == 0.0);
	CHECK(effect_gain(0.1, 0.2, 0.25) == doctest::Approx(1.0)); // Ramps shrink to fit.
}

TEST_CASE("pong effects: remote pulls toward the owner's mirrored stylus, low-passed and capped") {
	const PongConfig config;
	CHECK(mirror_left_right({ 0.03, -0.02, 0.01 }) == Vec3{ -0.03, -0.02, 0.01 });
	// The victim is player 0 (the device), the owner player 1, driven by the game: its
	// paddle 0.25 m to the world's +x of its avatar, 0.1 up, 0.05 toward -z.
	PongInput input;
	PongSim sim = device_sim(0, &input);
	input.players[1].avatar = { 0.0, 1.0, -2.0 };
	input.players[1].paddle_offset = { 0.25, 0.1, -0.05 };
	sim.set_input(input);
	// The owner's stylus in its own device frame: offset / scale, turned: (-0.05, 0.02, 0.01);
	// mirrored: (0.05, 0.02, 0.01).
	const Vec3 target{ 0.05, 0.02, 0.01 };
	HandSample hand;
	hand.position_m = { 0.01, 0.0, 0.0 };
	PongCommand remote = effect(0, PongEffectKind::REMOTE);
	remote.magnitude_n = 10.0; // Above the pull: uncapped.
	remote.use_default_magnitude = false;
	sim.apply(remote);
	// The target starts at the hand and follows at remote_cutoff_hz, and the effect ramps in:
	// after 0.1 s the pull is still well short of its law; after 1.1 s it is the law.
	const Vec3 early = run(sim, 0.1, hand);
	const Vec3 pull = (target - hand.position_m) * config.remote_stiffness_n_per_m;
	CHECK(length(early) < 0.5 * length(pull));
	const Vec3 settled = run(sim, 1.0, hand);
	CHECK(settled.x == doctest::Approx(pull.x).epsilon(1e-6));
	CHECK(settled.y == doctest::Approx(pull.y).epsilon(1e-6));
	CHECK(settled.z == doctest::Approx(pull.z).epsilon(1e-6));
	CHECK(pull.x == doctest::Approx(120.0 * 0.04));

	// The default cap: remote_max_force_n, along the same direction.
	sim.apply(effect(0, PongEffectKind::REMOTE));
	const Vec3 capped = run(sim, 1.0, hand);
	CHECK(length(capped) == doctest::Approx(config.remote_max_force_n));
	CHECK(length(cross(capped, pull)) < 1e-9);

	// Player 1 as the victim of player 0: the owner's offset is turned by player 0's frame (the
	// world's own), mirrored, and the force is in player 1's device space.
	PongInput far_input;
	PongSim far = device_sim(1, &far_input);
	far_input.players[0].avatar = { 0.0, 1.0, 2.0 };
	far_input.players[0].paddle_offset = { 0.25, 0.1, -0.05 };
	far.set_input(far_input);
	remote.player = 1;
	remote.owner = 0;
	far.apply(remote);
	const Vec3 far_pull = run(far, 1.0, hand);
	const Vec3 far_target{ -0.05, 0.02, -0.01 };
	CHECK(far_pull.x == doctest::Approx((far_target.x - hand.position_m.x) * config.remote_stiffness_n_per_m));
	CHECK(far_pull.z == doctest::Approx(far_target.z * config.remote_stiffness_n_per_m));
}

TEST_CASE("pong effects: clear_effects ends them at once, none does nothing, a new one of a kind restarts it") {
	PongSim sim = device_sim(0);
	const HandSample hand;
	sim.apply(effect(0, PongEffectKind::HEAVY));
	run(sim, 1.0, hand);
	PongState state;
	sim.fill_state(state);
	REQUIRE(state.effects.size() == 1);
	CHECK(state.effects[0].kind == PongEffectKind::HEAVY);
	CHECK(state.effects[0].remaining_s == doctest::Approx(PongConfig{}.mine_effect_duration_s - 1.0));
	sim.apply(effect(0, PongEffectKind::HEAVY)); // Restarts: the ramp again from zero.
	sim.step(PONG_DT, &hand);
	CHECK(sim.hand_forces().effects == Vec3{});
	sim.apply(effect(0, PongEffectKind::NONE));
	PongCommand clear;
	clear.type = PongCommandType::CLEAR_EFFECTS;
	sim.apply(clear);
	sim.step(PONG_DT, &hand);
	CHECK(sim.hand_forces().effects == Vec3{});
	sim.fill_state(state);
	CHECK(state.effects.size() == 0);
}
