// The remote-operation mine across the network (hand_effects.h): two victims' hands,
// each a light mass on the simulated device, each pulled toward the other's mirrored
// stylus as the network delivers it (60 Hz samples with jitter, 100 or 200 ms one way):
// a loop closes through the network. The energy in the loop (the hands' kinetic energy
// plus the couplings' potential) must not grow once nobody pushes, and must decay; the
// same run without the passivity rule must not (so these tests can fail).
// A one-way case: an owner that moves then stops, 200 ms late, a victim that settles.

#include "devices/simulated_device.h"
#include "pong/pong_test_support.h"
#include "renderers/pong/hand_effects.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numbers>
#include <random>
#include <string>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr double DT = 0.001;
constexpr double HAND_MASS_KG = 0.2; // A hand lightly holding a stylus: 0.1-0.3 kg.
constexpr double HAND_DAMPING_N_S_PER_M = 0.3; // Lightly damped.
constexpr double SAMPLE_PERIOD_S = 1.0 / 60.0;

// A hand on the simulated device: a mass with light damping under the device's force and
// an external push.
struct Hand {
	Vec3 position;
	Vec3 velocity;

	void step(const Vec3 &p_force) {
		velocity += (p_force - velocity * HAND_DAMPING_N_S_PER_M) * (DT / HAND_MASS_KG);
		position += velocity * DT;
	}
	double kinetic() const { return 0.5 * HAND_MASS_KG * length_squared(velocity); }
};

// One direction of the network: samples sent at 60 Hz (each up to 3 ms late), each
// delivered after the delay plus up to 20 ms of jitter; the receiver keeps the newest one
// sent (a late one overtaken by a newer one is dropped, as sequence numbers would).
class Link {
public:
	Link(double p_delay_s, unsigned p_seed) :
			delay_s_(p_delay_s), rng_(p_seed) {}

	void update(double p_now, const Hand &p_hand) {
		if (p_now >= next_send_s_) {
			std::uniform_real_distribution<double> jitter(0.0, 0.020);
			in_flight_.push_back({ p_now + delay_s_ + jitter(rng_), p_now, p_hand.position, p_hand.velocity });
			std::uniform_real_distribution<double> late(0.0, 0.003);
			next_send_s_ += SAMPLE_PERIOD_S + late(rng_) - 0.0015;
		}
		for (auto it = in_flight_.begin(); it != in_flight_.end();) {
			if (it->arrive_s <= p_now) {
				if (it->sent_s > latest_.sent_s) {
					latest_ = *it;
				}
				it = in_flight_.erase(it);
			} else {
				++it;
			}
		}
	}
	// What the receiver knows now.
	StylusSample sample(double p_now) const {
		return { latest_.position, latest_.velocity, latest_.sent_s < 0.0 ? 0.0 : p_now - latest_.sent_s };
	}

private:
	struct Packet {
		double arrive_s = 0.0;
		double sent_s = -1.0;
		Vec3 position;
		Vec3 velocity;
	};
	double delay_s_;
	std::mt19937 rng_;
	double next_send_s_ = 0.0;
	std::deque<Packet> in_flight_;
	Packet latest_;
};

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

EffectOrder remote_order(int p_owner, const PongConfig &p_config) {
	EffectOrder order;
	order.kind = PongEffectKind::REMOTE;
	order.magnitude_n = p_config.remote_max_force_n;
	order.duration_s = 60.0; // Longer than the run: the effect's own end must not hide anything.
	order.ramp_s = p_config.mine_effect_ramp_s;
	order.owner = p_owner;
	return order;
}

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
			// so E dips below zero (measured: -18.4 mJ at 100 ms, -10.1 mJ at 200 ms, about two
			// allowances at most), and the loop still loses its energy (below).
			CHECK(r.min_observer_j >= -3.0 * remote_allowance(config));
			// On its own the loop gains at most what the observers still allowed, within 5 %:
			// this measure counts a hand's motion twice for a moment (its kinetic energy, and
			// the stretch it gives the other hand's spring a delay later), which the observers,
			// each watching its own hand, rightly do not. Measured: at most +0.9 %.
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
	// Measured -0.64 mJ (the in-tick acceleration, as above).
	CHECK(min_observer >= -0.1 * remote_allowance(config));
	CHECK(energy_end < 0.2 * std::max(peak_after, 1e-6));
	// The victim ends where the owner's mirrored stylus stopped (within the spring's pull of
	// its damping).
	const Vec3 resting = mirror_left_right(owner.position);
	CHECK(length(victim.position - resting) < 0.01);
}

namespace {

struct WorkResult {
	double counted_j = 0.0; // HandEffects::remote_work_j at the end.
	double summed_j = 0.0; // F . v dt at the velocity each tick read (what a velocity observer books).
	// The work the forces really did on the simulated stylus: each tick's force times the
	// displacement it was held over (the next tick's step).
	double physical_j = 0.0;
	double physical_peak_j = 0.0;
	double peak_j = 0.0; // The largest running value of summed_j.
	double hand_travel_m = 0.0; // The stylus's largest distance from where it started.
	double allowance_j = 0.0;
};

// The mine's whole effect (the configured duration and ramps) on the simulated device's hand
// (the default device: a stylus held by a spring-damper hand at rest at the centre), the
// owner's stylus swinging 40 mm at 1.5 Hz and arriving p_one_way_s late.
WorkResult run_on_simulated_hand(bool p_passivity, double p_one_way_s) {
	PongConfig config;
	config.remote_passivity = p_passivity;
	HandEffects effects;
	effects.configure(config);
	SimulatedDevice device;
	REQUIRE(device.open().ok());
	EffectOrder order = remote_order(1, config);
	order.duration_s = config.mine_effect_duration_s;
	effects.start(order, Vec3{});
	Link link(p_one_way_s, 9u);
	Hand owner;
	WorkResult result;
	Vec3 held_force;
	Vec3 last_position;
	result.allowance_j = 0.5 * config.remote_max_force_n * config.remote_max_force_n / config.remote_stiffness_n_per_m;
	const double w = 2.0 * std::numbers::pi * 1.5;
	const int ticks = static_cast<int>(std::lround(config.mine_effect_duration_s / DT));
	for (int tick = 0; tick < ticks; ++tick) {
		const double now = tick * DT;
		owner.position = Vec3{ 0.04 * std::sin(w * now), 0.0, 0.0 };
		owner.velocity = Vec3{ 0.04 * w * std::cos(w * now), 0.0, 0.0 };
		link.update(now, owner);
		device.begin_tick(DT);
		DeviceState state;
		REQUIRE(device.read_state(state) == DeviceIo::OK);
		result.physical_j += dot(held_force, state.position_m - last_position);
		result.physical_peak_j = std::max(result.physical_peak_j, result.physical_j);
		last_position = state.position_m;
		StylusSample styluses[PONG_MAX_PLAYERS];
		styluses[1] = link.sample(now);
		const Vec3 force = effects.advance(DT, state.position_m, state.velocity_m_per_s, styluses);
		result.summed_j += dot(force, state.velocity_m_per_s) * DT;
		result.peak_j = std::max(result.peak_j, result.summed_j);
		result.hand_travel_m = std::max(result.hand_travel_m, length(state.position_m));
		ForceCommand command;
		command.force_n = force;
		device.write_force(command);
		held_force = force;
	}
	result.counted_j = effects.remote_work_j();
	return result;
}

} // namespace

TEST_CASE("pong remote latency: the coupling's work on the simulated hand, owner 100 ms late, stays within the allowance") {
	const WorkResult passive = run_on_simulated_hand(true, 0.1);
	const WorkResult active = run_on_simulated_hand(false, 0.1);
	MESSAGE("simulated hand, 100 ms one way: F.v booked " << passive.summed_j * 1e3 << " mJ (peak " << passive.peak_j * 1e3
														  << ") with the rule, " << active.summed_j * 1e3 << " mJ without; allowance "
														  << passive.allowance_j * 1e3 << " mJ; hand travel "
														  << passive.hand_travel_m * 1e3 << " / " << active.hand_travel_m * 1e3 << " mm; physical "
														  << passive.physical_j * 1e3 << " (peak " << passive.physical_peak_j * 1e3 << ") / "
														  << active.physical_j * 1e3 << " mJ");
	// The counter is the work the held forces really did on the stylus (the last tick's
	// force, held past the effect's end, is not booked: it is nearly zero after the ramp).
	CHECK(passive.counted_j == doctest::Approx(passive.physical_j).epsilon(1e-6));
	CHECK(active.counted_j == doctest::Approx(active.physical_j).epsilon(1e-6));
	// The hand really moves under the pull (the simulated device's hand is not rigid).
	CHECK(passive.hand_travel_m > 0.003);
	// With the rule the net work on the hand stays within one allowance at every tick, to the
	// in-tick overshoot (measured +0.4 %). An observer that books F . v dt at the velocity of
	// the tick before instead sees 9.2 mJ while the stylus really takes 33.6 mJ: the ZOH force
	// and the stylus's 80 Hz resonance on the hand's spring beat against it.
	CHECK(passive.physical_peak_j <= 1.01 * passive.allowance_j);
	// Without it the swinging, delayed target pumps the hand all along: several allowances.
	CHECK(active.counted_j > 3.0 * passive.allowance_j);
}

TEST_CASE("pong remote latency: the sim reports the coupling's work in its state, and clearing the effects zeroes it") {
	PongSim sim;
	PongInput input = idle_input();
	input.local_player = 0;
	input.players[0].kinematic = false;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[1].avatar = { 0.0, 1.0, -2.0 };
	input.players[1].paddle_offset = { 0.2, 0.0, 0.0 };
	sim.set_input(input);
	PongCommand command;
	command.type = PongCommandType::EFFECT;
	command.player = 0;
	command.owner = 1;
	command.kind = PongEffectKind::REMOTE;
	sim.apply(command);
	HandSample hand; // Moving toward the pull's side at 5 cm/s: the coupling does work on it.
	hand.velocity_m_per_s = { 0.05, 0.0, 0.0 };
	for (int k = 0; k < 500; ++k) {
		sim.step(DT, &hand);
		hand.position_m += hand.velocity_m_per_s * DT;
	}
	PongState state;
	sim.fill_state(state);
	CHECK(state.remote_work_j == doctest::Approx(sim.effects().remote_work_j()));
	CHECK(state.remote_work_j > 0.0);
	command.type = PongCommandType::CLEAR_EFFECTS;
	sim.apply(command);
	sim.fill_state(state);
	CHECK(state.remote_work_j == 0.0);
}
