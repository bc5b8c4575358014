// The server's check of a master's ball (renderers/pong/ball_witness.h): an honest master's
// stream, made by the servo's own simulation, passes whole (free flight, floor bounces, a
// correction gliding in, a paddle hit, reordering); a forged one (a teleport, the ball
// bouncing in the opponent's territory) is refused; the verdict crosses the renderer port as
// bytes.

#include "pong/pong_test_support.h"

#include "renderers/pong/ball_witness.h"
#include "renderers/pong/pong_port.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

// The master streams a state every 8 ms (125 Hz, PongNetPlay.MAX_STREAM_HZ).
constexpr int STREAM_TICKS = 8;
// Each state is this old when it reaches the server.
constexpr double AGE_S = 0.12;

// A master's stream: its sim, stepped at the servo period, and the states it sent.
struct Master {
	PongSim sim;
	std::vector<PongWitnessCheck> sent;
	std::vector<PongState> states; // The sim's state at each one (the server's paddles then).
	std::vector<PongEvent> floors;

	void run(int p_ticks, int p_epoch = 1) {
		for (int k = 1; k <= p_ticks; ++k) {
			sim.step(PONG_DT, nullptr);
			for (const PongEvent &event : take_events(sim)) {
				if (event.type == PongEventType::FLOOR) {
					floors.push_back(event);
				}
			}
			if (k % STREAM_TICKS == 0) {
				PongState state;
				sim.fill_state(state);
				PongWitnessCheck check;
				check.epoch = p_epoch;
				check.time_s = state.time_s;
				check.position = state.ball_position + state.ball_correction; // As PongNetPlay streams it.
				check.velocity = state.ball_velocity;
				check.spin = state.ball_spin;
				check.age_s = AGE_S;
				sent.push_back(check);
				states.push_back(state);
			}
		}
	}
};

// The server: notes the paddles as its servo had them (at the master's times) and checks each
// state AGE_S after it was sent. Returns the verdicts.
std::vector<PongWitnessVerdict> judge(BallWitness &r_witness, const Master &p_master, const PongConfig &p_config,
		bool p_with_paddles = true, bool p_beginner = false) {
	std::vector<PongWitnessVerdict> verdicts;
	for (size_t i = 0; i < p_master.sent.size(); ++i) {
		if (p_with_paddles) {
			r_witness.note_paddles(p_master.states[i]);
		}
		verdicts.push_back(r_witness.check(p_master.sent[i], p_master.sent[i].time_s + AGE_S, p_config, p_beginner));
	}
	return verdicts;
}

size_t count(const std::vector<PongWitnessVerdict> &p_verdicts, WitnessVerdict p_kind) {
	return size_t(std::count_if(p_verdicts.begin(), p_verdicts.end(),
			[&](const PongWitnessVerdict &p_verdict) { return p_verdict.verdict == p_kind; }));
}

// An honest master's stream (a ball flying in territory 0), then a cheater's of p_ticks: a
// ball of its own making bouncing in place in territory 1, its states consistent among
// themselves.
void honest_then_forged(const PongConfig &p_config, int p_ticks, Master &r_honest, Master &r_forged) {
	r_honest.sim.configure(p_config);
	r_honest.sim.set_input(idle_input());
	r_honest.sim.apply(set_ball({ 0.2, 1.0, 1.2 }, { 0.0, 0.0, 0.5 }));
	r_honest.run(200);
	r_forged.sim.configure(p_config);
	r_forged.sim.set_input(idle_input());
	r_forged.sim.apply(set_ball({ 0.4, 1.2, -2.0 }, { 0.0, 0.0, 0.0 }));
	r_forged.run(p_ticks);
}

double worst_miss(const std::vector<PongWitnessVerdict> &p_verdicts) {
	double worst = 0.0;
	for (const PongWitnessVerdict &verdict : p_verdicts) {
		worst = std::max(worst, verdict.miss_m);
	}
	return worst;
}

} // namespace

TEST_CASE("ball witness: an honest master's free flight passes whole and its floor bounces are the servo's") {
	PongConfig config;
	Master master;
	master.sim.configure(config);
	master.sim.set_input(idle_input());
	master.sim.apply(set_ball({ 0.3, 1.2, 1.5 }, { 0.8, 1.0, -2.5 }, { 5.0, 0.0, 2.0 }));
	master.run(3000); // Three seconds: several floor and wall bounces, spin at each.
	BallWitness witness;
	const std::vector<PongWitnessVerdict> verdicts = judge(witness, master, config);
	REQUIRE(master.floors.size() >= 3);
	CHECK(verdicts.front().verdict == WitnessVerdict::ANCHOR);
	CHECK(count(verdicts, WitnessVerdict::FLOWN) == verdicts.size() - 1);
	CHECK(worst_miss(verdicts) < 1e-6); // The same laws, the same steps.
	std::vector<PongWitnessBounce> bounces;
	for (const PongWitnessVerdict &verdict : verdicts) {
		bounces.insert(bounces.end(), verdict.bounces.begin(), verdict.bounces.end());
	}
	REQUIRE(bounces.size() == master.floors.size());
	for (size_t b = 0; b < bounces.size(); ++b) {
		CHECK(length(bounces[b].position - master.floors[b].position) < 1e-6);
	}
	// The ago of the first bounce: it happened that long before the check of the state after it.
	const PongWitnessCheck *after = nullptr;
	for (const PongWitnessCheck &check : master.sent) {
		if (check.time_s >= master.floors[0].time_s) {
			after = &check;
			break;
		}
	}
	REQUIRE(after != nullptr);
	CHECK(bounces[0].ago_s == doctest::Approx(AGE_S + after->time_s - master.floors[0].time_s).epsilon(1e-6));
}

TEST_CASE("ball witness: a new master's ball with a correction still gliding in passes") {
	PongConfig config;
	Master master;
	master.sim.configure(config);
	master.sim.set_input(idle_input());
	master.sim.apply(set_ball({ 0.0, 1.0, -0.5 }, { 0.5, 0.0, 2.0 }));
	master.sim.step(PONG_DT, nullptr);
	// The hand-off's state is 0.6 m from the follower copy: the correction glides it in while
	// the new master streams (its stream is the corrected ball).
	PongCommand correct = set_ball({ 0.4, 1.3, 0.1 }, { -0.5, 1.5, 3.0 }, { 0.0, 20.0, 0.0 });
	correct.type = PongCommandType::CORRECT_BALL;
	master.sim.apply(correct);
	master.run(1500);
	BallWitness witness;
	const std::vector<PongWitnessVerdict> verdicts = judge(witness, master, config);
	CHECK(count(verdicts, WitnessVerdict::UNREACHABLE) == 0);
	CHECK(count(verdicts, WitnessVerdict::STRUCK) == 0);
	MESSAGE("worst miss while the correction glided: " << worst_miss(verdicts) << " m");
	CHECK(worst_miss(verdicts) < WITNESS_POSITION_M);
}

TEST_CASE("ball witness: a paddle's hit is struck only where a paddle was near the ball, ours or the master's own pose") {
	PongConfig config;
	config.air_linear_decel_m_per_s2 = 0.0;
	Master master;
	master.sim.configure(config);
	PongInput input = idle_input();
	input.beginner = true; // A level flight, past the settling second, straight into the paddle.
	input.players[1] = game_paddle({ 0.0, config.beginner_height_m, -2.5 }, { 0.0, 0.0, 1.0 });
	master.sim.set_input(input);
	master.sim.apply(set_ball({ 0.0, config.beginner_height_m, 1.0 }, { 0.0, 0.0, -2.0 }));
	master.run(2500);
	PongState last;
	master.sim.fill_state(last);
	REQUIRE(last.paddle_contacts == 1);
	REQUIRE(master.sent.front().time_s + WITNESS_SETTLE_S < 1.6); // The hit comes after it.
	BallWitness with_paddles;
	const std::vector<PongWitnessVerdict> fair = judge(with_paddles, master, config, true, true);
	CHECK(count(fair, WitnessVerdict::UNREACHABLE) == 0);
	CHECK(count(fair, WitnessVerdict::STRUCK) >= 1);
	// The same stream to a server that knew of no paddle: the hit cannot be explained.
	BallWitness blind;
	const std::vector<PongWitnessVerdict> unexplained = judge(blind, master, config, false, true);
	CHECK(count(unexplained, WitnessVerdict::UNREACHABLE) >= 1);
	// Its own paddle's poses, stamped with its clock, explain it without our copy of it.
	BallWitness told;
	size_t refused = 0;
	size_t struck = 0;
	for (size_t i = 0; i < master.sent.size(); ++i) {
		PongWitnessPose pose;
		pose.epoch = master.sent[i].epoch;
		pose.time_s = master.states[i].time_s;
		pose.center = master.states[i].paddle_centers[1];
		told.note_pose(pose);
		const WitnessVerdict verdict =
				told.check(master.sent[i], master.sent[i].time_s + AGE_S, config, true).verdict;
		refused += verdict == WitnessVerdict::UNREACHABLE ? 1 : 0;
		struck += verdict == WitnessVerdict::STRUCK ? 1 : 0;
	}
	CHECK(refused == 0);
	CHECK(struck >= 1);
}

TEST_CASE("ball witness: a teleport is refused and the states after it are checked from the last one kept") {
	PongConfig config;
	Master master;
	master.sim.configure(config);
	master.sim.set_input(idle_input());
	master.sim.apply(set_ball({ -0.5, 1.5, 1.0 }, { 0.3, 0.5, -1.0 }));
	master.run(400);
	BallWitness witness;
	for (size_t i = 0; i < 20; ++i) {
		witness.check(master.sent[i], master.sent[i].time_s + AGE_S, config, false);
	}
	PongWitnessCheck teleport = master.sent[20];
	teleport.position.z -= 2.0; // Into the other half.
	const PongWitnessVerdict refused = witness.check(teleport, teleport.time_s + AGE_S, config, false);
	CHECK(refused.verdict == WitnessVerdict::UNREACHABLE);
	CHECK(refused.miss_m == doctest::Approx(2.0).epsilon(0.01));
	CHECK(refused.bounces.empty());
	for (size_t i = 21; i < master.sent.size(); ++i) {
		CHECK(witness.check(master.sent[i], master.sent[i].time_s + AGE_S, config, false).verdict ==
				WitnessVerdict::FLOWN);
	}
}

TEST_CASE("ball witness: while a new master's ball settles a jump in its own territory starts the flight anew") {
	PongConfig config;
	Master master;
	master.sim.configure(config);
	master.sim.set_input(idle_input());
	master.sim.apply(set_ball({ -0.5, 1.5, 1.0 }, { 0.3, 0.5, 0.5 }));
	master.run(2000); // Two seconds in territory 0, the master's.
	BallWitness witness;
	for (size_t i = 0; i < 20; ++i) {
		witness.check(master.sent[i], master.sent[i].time_s + AGE_S, config, false);
	}
	PongWitnessCheck glide = master.sent[20];
	glide.position.x += 0.4; // Still territory 0.
	CHECK(witness.check(glide, glide.time_s + AGE_S, config, false).verdict == WitnessVerdict::ANCHOR);
	PongWitnessCheck across = master.sent[21];
	across.position.z = -1.5; // Territory 1, past the margin: never taken so.
	CHECK(witness.check(across, across.time_s + AGE_S, config, false).verdict == WitnessVerdict::UNREACHABLE);
	// A settling stream whose ball turns up in mid-air bounced: in its own territory that is a
	// floor bounce there; across the border (within the margin) it is not reported.
	PongWitnessCheck falling = master.sent[22];
	falling.velocity = { 0.0, -3.0, 0.0 };
	falling.position = { 0.2, 1.0, 0.5 };
	witness.check(falling, falling.time_s + AGE_S, config, false);
	PongWitnessCheck turned = master.sent[23];
	turned.position = { 0.2, 0.98, 0.5 };
	turned.velocity = { 0.0, 2.5, 0.0 };
	const PongWitnessVerdict bounced = witness.check(turned, turned.time_s + AGE_S, config, false);
	CHECK(bounced.verdict == WitnessVerdict::ANCHOR);
	REQUIRE(bounced.bounces.size() == 1);
	CHECK(bounced.bounces[0].position.y == doctest::Approx(config.ball_radius_m));
	CHECK(bounced.bounces[0].position.z == doctest::Approx(0.5));
	PongWitnessCheck falling_across = master.sent[24];
	falling_across.velocity = { 0.0, -3.0, 0.0 };
	falling_across.position = { 0.2, 1.0, -0.5 };
	witness.check(falling_across, falling_across.time_s + AGE_S, config, false);
	PongWitnessCheck turned_across = master.sent[25];
	turned_across.position = { 0.2, 0.98, -0.5 };
	turned_across.velocity = { 0.0, 2.5, 0.0 };
	const PongWitnessVerdict across_bounce = witness.check(turned_across, turned_across.time_s + AGE_S, config, false);
	CHECK(across_bounce.verdict == WitnessVerdict::ANCHOR);
	CHECK(across_bounce.bounces.empty());
	// Past the settling second the same jump in its own territory is refused.
	const size_t late = size_t(1.2 / (STREAM_TICKS * PONG_DT));
	for (size_t i = 26; i < late; ++i) {
		PongWitnessCheck check = master.sent[i];
		check.position.x += 0.4; // On the glide's flight.
		witness.check(check, check.time_s + AGE_S, config, false);
	}
	PongWitnessCheck jump = master.sent[late];
	jump.position.x -= 0.4; // Back where the master's own ball is: a jump of 0.4 m.
	CHECK(witness.check(jump, jump.time_s + AGE_S, config, false).verdict == WitnessVerdict::UNREACHABLE);
}

TEST_CASE("ball witness: the issue's forged ball bouncing in the opponent's territory is refused, bounces and all") {
	PongConfig config;
	// The cheater's ball bounces in territory 1 for 1.8 s (past WITNESS_MAX_GAP_S).
	Master honest;
	Master forged;
	honest_then_forged(config, 1800, honest, forged);
	BallWitness witness;
	judge(witness, honest, config);
	const double shift = honest.sent.back().time_s + 0.008 - forged.sent.front().time_s;
	size_t refused = 0;
	size_t bounces = 0;
	for (PongWitnessCheck check : forged.sent) {
		check.time_s += shift;
		const PongWitnessVerdict verdict = witness.check(check, check.time_s + AGE_S, config, false);
		refused += verdict.verdict == WitnessVerdict::UNREACHABLE ? 1 : 0;
		bounces += verdict.bounces.size();
	}
	// Every one, however long the forgery goes on: the master never fell silent.
	CHECK(refused == forged.sent.size());
	CHECK(bounces == 0);
	CHECK(forged.floors.size() >= 2);
}

TEST_CASE("ball witness: a master back from a silence with the ball far from its territory is not anchored there") {
	PongConfig config;
	// Silent past WITNESS_MAX_GAP_S, then its forged ball: each state is old (not played, no
	// anchor to forge from), however long it goes on.
	Master honest;
	Master forged;
	honest_then_forged(config, 1000, honest, forged);
	BallWitness witness;
	judge(witness, honest, config);
	const double shift = honest.sent.back().time_s + WITNESS_MAX_GAP_S + 0.5 - forged.sent.front().time_s;
	size_t old = 0;
	for (PongWitnessCheck check : forged.sent) {
		check.time_s += shift;
		check.territory = 0;
		old += witness.check(check, check.time_s + AGE_S, config, false).verdict == WitnessVerdict::OLD ? 1 : 0;
	}
	CHECK(old == forged.sent.size());
	// The same silence with the ball back in its own territory starts a flight there.
	PongWitnessCheck back = forged.sent.back();
	back.time_s += shift + 0.008;
	back.position = { 0.4, 1.0, 1.5 };
	CHECK(witness.check(back, back.time_s + AGE_S, config, false).verdict == WitnessVerdict::ANCHOR);
}

TEST_CASE("ball witness: reordered states are checked from the state before them, old ones are not judged") {
	PongConfig config;
	Master master;
	master.sim.configure(config);
	master.sim.set_input(idle_input());
	master.sim.apply(set_ball({ 0.0, 1.4, 0.5 }, { 1.0, 2.0, -2.0 }));
	master.run(2000);
	std::vector<PongWitnessCheck> shuffled = master.sent;
	for (size_t i = 1; i + 2 < shuffled.size(); i += 3) {
		std::swap(shuffled[i], shuffled[i + 2]); // Every third state overtaken by two.
	}
	BallWitness witness;
	size_t unreachable = 0;
	for (const PongWitnessCheck &check : shuffled) {
		unreachable += witness.check(check, check.time_s + AGE_S, config, false).verdict == WitnessVerdict::UNREACHABLE;
	}
	CHECK(unreachable == 0);
	// Older than every state of its epoch: not judged. An old epoch: not judged.
	PongWitnessCheck first = master.sent.front();
	BallWitness fresh;
	fresh.check(master.sent[5], master.sent[5].time_s + AGE_S, config, false);
	CHECK(fresh.check(first, first.time_s + AGE_S, config, false).verdict == WitnessVerdict::OLD);
	PongWitnessCheck next_epoch = master.sent[6];
	next_epoch.epoch = 2;
	next_epoch.position = { 1.0, 0.5, -2.0 };
	CHECK(fresh.check(next_epoch, next_epoch.time_s + AGE_S, config, false).verdict == WitnessVerdict::ANCHOR);
	CHECK(fresh.check(master.sent[7], master.sent[7].time_s + AGE_S, config, false).verdict == WitnessVerdict::OLD);
	// A copy of a state kept is not judged; another state of the same moment is refused.
	CHECK(fresh.check(next_epoch, next_epoch.time_s + AGE_S, config, false).verdict == WitnessVerdict::OLD);
	PongWitnessCheck contradiction = next_epoch;
	contradiction.position.y += 0.3;
	CHECK(fresh.check(contradiction, contradiction.time_s + AGE_S, config, false).verdict ==
			WitnessVerdict::UNREACHABLE);
}

TEST_CASE("ball witness: through the renderer port the check is bytes in and the verdict bytes out") {
	PongChannels channels;
	PongPort port(channels);
	PongConfig config;
	channels.settings.store(config);
	PongWitnessCheck check;
	check.epoch = 3;
	check.time_s = 1.0;
	check.position = { 0.0, 1.0, 1.0 };
	check.velocity = { 0.0, 0.0, 1.0 };
	REQUIRE(port.receive(encode(check)).ok());
	PongWitnessCheck teleport = check;
	teleport.time_s = 1.01;
	teleport.position = { 0.0, 1.0, -2.0 };
	REQUIRE(port.receive(encode(teleport)).ok());
	std::vector<uint8_t> bytes;
	REQUIRE(port.give(PongWitnessVerdict::SCHEMA_ID, bytes).ok());
	PongWitnessVerdict verdict;
	REQUIRE(decode(std::span<const uint8_t>(bytes), verdict).ok());
	CHECK(verdict.verdict == WitnessVerdict::UNREACHABLE);
	CHECK(verdict.gap_s == doctest::Approx(0.01));
	// A check that is no check (NaN) is refused with its field named; the verdict stays.
	PongWitnessCheck broken = check;
	broken.time_s = 1.02;
	broken.velocity.x = std::nan("");
	const Status refused = port.receive(encode(broken));
	CHECK_FALSE(refused.ok());
	CHECK(std::string(refused.message()).find("velocity") != std::string::npos);
	REQUIRE(port.give(PongWitnessVerdict::SCHEMA_ID, bytes).ok());
	REQUIRE(decode(std::span<const uint8_t>(bytes), verdict).ok());
	CHECK(verdict.verdict == WitnessVerdict::UNREACHABLE);
}
