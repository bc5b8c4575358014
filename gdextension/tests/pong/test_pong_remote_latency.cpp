// The remote-operation mine across the network (hand_effects.h): two victims' hands,
// each a light mass on the simulated device, each pulled toward the other's mirrored
// stylus as the network delivers it (60 Hz samples with jitter, 100 or 200 ms one way):
// a loop closes through the network. The energy in the loop (the hands' kinetic energy
// plus the couplings' potential) must not grow once nobody pushes, and must decay; the
// same run without the passivity rule must not (so these tests can fail).
// A one-way case: an owner that moves then stops, 200 ms late, a victim that settles. The
// coupling's work on the simulated device's own hand: test_pong_remote_work.cpp.

#include "pong/remote_network.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr double DT = 0.001;
// What the passivity observer allows a coupling to deliver, net: F_cap^2 / (2 k_f).
double remote_allowance(const PongConfig &p_config) {
	return 0.5 * p_config.remote_max_force_n * p_config.remote_max_force_n / p_config.remote_stiffness_n_per_m;
}

// The coupling's potential energy at a stretch p_d: a spring up to the cap's stretch, then a
// constant force (the capped force does work F_cap per metre further).
double coupling_potential(double p_d, const PongConfig &p_config) {
	const double k = p_config.remote_stiffness_n_per_m;
	const double d_cap = p_config.remote_max_force_n / k;
	return p_d <= d_cap ? 0.5 * k * p_d * p_d : 0.5 * k * d_cap * d_cap + p_config.remote_max_force_n * (p_d - d_cap);
}

struct LoopResult {
	// When the loop is on its own: the push's last samples delivered and followed.
	double energy_at_stop_j = 0.0;
	double budget_at_stop_j = 0.0; // The two observers' E then.
	double peak_after_stop_j = 0.0;
	double energy_end_j = 0.0;
	double decay_time_s = -1.0; // From the push's end to below 10 % of the energy at the stop.
	double min_observer_j = 1e9;
	double max_force_n = 0.0;
	bool finite = true;
};

// Players 0 and 1 under each other's remote mine, each link p_one_way_s late. Player 0's
// hand is pushed (the "owner moving") for p_push_s, then nobody pushes for p_after_s.
LoopResult run_mutual_remote(bool p_passivity, double p_one_way_s, unsigned p_seed, double p_push_s = 1.5,
		double p_after_s = 8.0) {
	PongConfig config;
	config.remote_passivity = p_passivity;
	HandEffects effects[2];
	Hand hands[2];
	hands[1].position = { -0.01, 0.005, 0.0 };
	Link links[2] = { Link(p_one_way_s, p_seed), Link(p_one_way_s, p_seed * 7u + 1u) }; // links[p]: p's stylus out.
	for (int p = 0; p < 2; ++p) {
		effects[p].configure(config);
		effects[p].start(remote_order(1 - p, config), hands[p].position);
	}
	const Vec3 push_direction = normalized_or_zero(Vec3{ 1.0, 0.5, -0.3 });
	LoopResult result;
	const int ticks = static_cast<int>(std::lround((p_push_s + p_after_s) / DT));
	for (int tick = 0; tick < ticks; ++tick) {
		const double now = tick * DT;
		StylusSample styluses[PONG_MAX_PLAYERS];
		for (int p = 0; p < 2; ++p) {
			links[p].update(now, hands[p]);
		}
		Vec3 forces[2];
		for (int p = 0; p < 2; ++p) {
			styluses[1 - p] = links[1 - p].sample(now);
			forces[p] = effects[p].advance(DT, hands[p].position, hands[p].velocity, styluses);
			result.finite = result.finite && is_finite(forces[p]);
			result.max_force_n = std::max(result.max_force_n, length(forces[p]));
			result.min_observer_j = std::min(result.min_observer_j, effects[p].remote_energy_j());
		}
		const bool pushing = now < p_push_s;
		// A cosine push: the hand swings about where it started (about 16 mm at 2 Hz) instead of
		// drifting off.
		const Vec3 push = pushing ? push_direction * (0.5 * std::cos(2.0 * std::numbers::pi * 2.0 * now)) : Vec3{};
		hands[0].step(forces[0] + push);
		hands[1].step(forces[1]);
		double energy = 0.0;
		for (int p = 0; p < 2; ++p) {
			energy += hands[p].kinetic() + coupling_potential(length(effects[p].remote_target_m() - hands[p].position), config);
		}
		// The push's last samples are still in flight for the delay plus the jitter, and the
		// target's low-pass follows them for a few of its 26 ms time constants: the loop is
		// on its own from then on.
		if (now < p_push_s + p_one_way_s + 0.25) {
			result.energy_at_stop_j = energy;
			result.budget_at_stop_j = effects[0].remote_energy_j() + effects[1].remote_energy_j();
			continue;
		}
		result.peak_after_stop_j = std::max(result.peak_after_stop_j, energy);
		if (result.decay_time_s < 0.0 && energy < 0.1 * result.energy_at_stop_j) {
			result.decay_time_s = now - p_push_s;
		}
		result.energy_end_j = energy;
	}
	return result;
}

void report(const std::string &p_name, const LoopResult &p_result) {
	MESSAGE(p_name << ": energy at the stop " << p_result.energy_at_stop_j * 1e3 << " mJ, peak after "
				   << p_result.peak_after_stop_j * 1e3 << " mJ, at the end " << p_result.energy_end_j * 1e3
				   << " mJ, decay to 10 % in " << p_result.decay_time_s << " s, observer min "
				   << p_result.min_observer_j * 1e3 << " mJ, |F| max " << p_result.max_force_n << " N");
}

} // namespace

TEST_CASE("pong remote latency: two hands under each other's mine across 100 and 200 ms one way lose their energy") {
	const PongConfig config;
	for (const double one_way : { 0.1, 0.2 }) {
		for (const unsigned seed : { 1u, 2u, 3u }) {
			CAPTURE(one_way);
			CAPTURE(seed);
			const LoopResult r = run_mutual_remote(true, one_way, seed);
			if (seed == 1u) {
				report(one_way < 0.15 ? "passive, 100 ms each way" : "passive, 200 ms each way", r);
			}
			REQUIRE(r.finite);
			CHECK(r.max_force_n <= config.remote_max_force_n + 1e-9);
			// The observer books the work each held force really did; the controller limits the
			// next force by its work at the present velocity, and the hand's own acceleration
			// within the tick makes the real work a little larger each time the controller acts,
			// so E dips below zero (by up to about two allowances: docs/renderers.md), and the
			// loop still loses its energy (below).
			CHECK(r.min_observer_j >= -3.0 * remote_allowance(config));
			// On its own the loop gains at most what the observers still allowed, within 5 %:
			// this measure counts a hand's motion twice for a moment (its kinetic energy, and
			// the stretch it gives the other hand's spring a delay later), which the observers,
			// each watching its own hand, rightly do not (the measured excess: docs/renderers.md).
			CHECK(r.peak_after_stop_j <= 1.05 * r.energy_at_stop_j + std::max(r.budget_at_stop_j, 0.0));
			// ...and it decays: below 10 % of the energy at the stop within the 8 s.
			CHECK(r.energy_at_stop_j > 1e-4); // The push did put energy in.
			CHECK(r.decay_time_s >= 0.0);
			CHECK(r.energy_end_j < 0.1 * r.energy_at_stop_j);
		}
	}
}

TEST_CASE("pong remote latency: without the passivity rule the same loop keeps its energy (the documented failure)") {
	// Kept so the test above is known to have teeth: the delayed springs pump the hands up to
	// the force cap and the oscillation does not die out.
	const PongConfig config;
	for (const double one_way : { 0.1, 0.2 }) {
		CAPTURE(one_way);
		const LoopResult r = run_mutual_remote(false, one_way, 1u);
		report(one_way < 0.15 ? "no passivity, 100 ms each way" : "no passivity, 200 ms each way", r);
		REQUIRE(r.finite);
		CHECK(r.max_force_n <= config.remote_max_force_n + 1e-9); // The cap still holds.
		CHECK(r.energy_end_j > 0.5 * r.energy_at_stop_j); // It does not decay...
		CHECK(r.min_observer_j < -0.01); // ...and the observer sees the coupling pump > 10 mJ.
	}
}

TEST_CASE("pong remote latency: a victim follows an owner 200 ms late, and settles when the owner stops") {
	PongConfig config;
	HandEffects effects;
	effects.configure(config);
	Hand victim;
	effects.start(remote_order(1, config), victim.position);
	Link link(0.2, 5u);
	Hand owner; // Scripted: it moves 2 s, then holds still.
	double energy_at_stop = 0.0;
	double peak_after = 0.0;
	double energy_end = 0.0;
	double min_observer = 1e9;
	for (int tick = 0; tick < 8000; ++tick) {
		const double now = tick * DT;
		const bool moving = now < 2.0;
		const double w = 2.0 * std::numbers::pi * 0.7;
		owner.position = moving ? Vec3{ 0.03 * std::sin(w * now), 0.015 * std::sin(2.0 * w * now), 0.0 }
								: Vec3{ 0.03 * std::sin(w * 2.0), 0.015 * std::sin(2.0 * w * 2.0), 0.0 };
		owner.velocity = moving ? Vec3{ 0.03 * w * std::cos(w * now), 0.03 * w * std::cos(2.0 * w * now), 0.0 } : Vec3{};
		link.update(now, owner);
		StylusSample styluses[PONG_MAX_PLAYERS];
		styluses[1] = link.sample(now);
		const Vec3 force = effects.advance(DT, victim.position, victim.velocity, styluses);
		REQUIRE(is_finite(force));
		CHECK(length(force) <= config.remote_max_force_n + 1e-9);
		victim.step(force);
		min_observer = std::min(min_observer, effects.remote_energy_j());
		const double energy =
				victim.kinetic() + coupling_potential(length(effects.remote_target_m() - victim.position), config);
		if (now < 2.0) {
			energy_at_stop = energy;
		} else if (now > 2.5) { // The last samples are in flight for up to 0.22 s.
			peak_after = std::max(peak_after, energy);
			energy_end = energy;
		}
	}
	MESSAGE("one way 200 ms: energy at the stop " << energy_at_stop * 1e3 << " mJ, peak after the last sample "
												  << peak_after * 1e3 << " mJ, at the end " << energy_end * 1e3
												  << " mJ, observer min " << min_observer * 1e3 << " mJ");
	// Slightly below zero from the in-tick acceleration, as above (docs/renderers.md).
	CHECK(min_observer >= -0.1 * remote_allowance(config));
	CHECK(energy_end < 0.2 * std::max(peak_after, 1e-6));
	// The victim ends where the owner's mirrored stylus stopped (within the spring's pull of
	// its damping).
	const Vec3 resting = mirror_left_right(owner.position);
	CHECK(length(victim.position - resting) < 0.01);
}
