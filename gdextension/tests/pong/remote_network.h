#pragma once

// The network between two Pong players under the remote-operation mine, for the doctests
// (test_pong_remote_latency.cpp, test_pong_remote_work.cpp): a hand on the simulated
// device, one direction of the network, and the mine's order.

#include "pong/pong_test_support.h"
#include "renderers/pong/hand_effects.h"

#include <deque>
#include <random>

namespace haptics::test {

inline constexpr double HAND_MASS_KG = 0.2; // A hand lightly holding a stylus: 0.1-0.3 kg.
inline constexpr double HAND_DAMPING_N_S_PER_M = 0.3; // Lightly damped.
inline constexpr double SAMPLE_PERIOD_S = 1.0 / 60.0;

// A hand on the simulated device: a mass with light damping under the device's force and
// an external push.
struct Hand {
	Vec3 position;
	Vec3 velocity;

	void step(const Vec3 &p_force) {
		velocity += (p_force - velocity * HAND_DAMPING_N_S_PER_M) * (PONG_DT / HAND_MASS_KG);
		position += velocity * PONG_DT;
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

// Player p_owner's remote mine, longer than any run: the effect's own end must not hide
// anything.
inline EffectOrder remote_order(int p_owner, const PongConfig &p_config) {
	EffectOrder order;
	order.kind = PongEffectKind::REMOTE;
	order.magnitude_n = p_config.remote_max_force_n;
	order.duration_s = 60.0; // Longer than the run: the effect's own end must not hide anything.
	order.ramp_s = p_config.mine_effect_ramp_s;
	order.owner = p_owner;
	return order;
}

} // namespace haptics::test
