// Tick-cost micro-benchmarks: how long the pieces of one servo tick take, without the
// thread, the sleep or the scheduler in the way.

#include "bench_report.h"

#include "core/servo/input_vector.h"
#include "core/servo/telemetry.h"
#include "core/servo/transients.h"
#include "renderers/constraint/constraint_port.h"
#include "renderers/movement/force_model.h"
#include "renderers/movement/smoothing_filter.h"
#include "renderers/pong/pong_port.h"
#include "renderers/pong/pong_sim.h"
#include "system/haptics_system.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../tests/test_proxy_geometry.h"

namespace haptics::bench {

namespace {

constexpr int BATCHES = 2000;
constexpr int PER_BATCH = 200;

volatile double g_sink = 0.0; // Keeps results alive so the optimiser cannot drop the work.

template <typename Work>
MicroResult measure(const char *p_name, Work p_work) {
	std::vector<double> per_call_ns;
	per_call_ns.reserve(BATCHES);
	for (int b = 0; b < BATCHES; ++b) {
		const auto begin = std::chrono::steady_clock::now();
		for (int n = 0; n < PER_BATCH; ++n) {
			p_work(n);
		}
		const auto end = std::chrono::steady_clock::now();
		per_call_ns.push_back(std::chrono::duration<double, std::nano>(end - begin).count() / PER_BATCH);
	}
	std::sort(per_call_ns.begin(), per_call_ns.end());
	MicroResult result;
	result.name = p_name;
	result.median_ns = per_call_ns[per_call_ns.size() / 2];
	result.p99_ns = per_call_ns[per_call_ns.size() * 99 / 100];
	return result;
}

// A busy frame: a corner (two contacts, one with its own material), a crate on the head,
// water.
Frame busy_frame() {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	add_contact(frame, { -1.0, 0.0, 0.0 }, ContactMaterial{ 3.0, 0.5 });
	add_contact(frame, { -0.7, 0.7, 0.0 });
	add_resting(frame, { 0.0, -1.0, 0.0 }, 0.8);
	set_water(frame, true, 0.4, 0.3);
	frame.velocity_m_per_s = { 1.2, -0.3, 0.0 };
	return frame;
}

// Player 0 holds the device paddle flat at (0, 1, 2) with spin mode on; player 1 out of play.
PongInput pong_bench_input() {
	PongInput input;
	input.local_player = 0;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[0].normal = { 0.0, 1.0, 0.0 };
	input.players[0].spin = true;
	input.players[1].active = false;
	return input;
}

PongCommand pong_bench_command(PongCommandType p_type, PongEffectKind p_kind = PongEffectKind::NONE) {
	PongCommand command;
	command.type = p_type;
	command.kind = p_kind;
	command.position = { 0.0, 1.0 + PongConfig{}.ball_radius_m, 2.0 }; // Resting on the paddle.
	command.spin = { 0.0, 30.0, 0.0 };
	return command;
}

std::string with_contact_share(const char *p_name, uint64_t p_contact_ticks, uint64_t p_ticks) {
	char name[160];
	std::snprintf(name, sizeof(name), "%s (in contact %.0f%%)", p_name,
			100.0 * static_cast<double>(p_contact_ticks) / static_cast<double>(p_ticks));
	return name;
}

} // namespace

std::vector<MicroResult> run_micro_benchmarks() {
	std::vector<MicroResult> results;
	const Frame frame = busy_frame();
	const ForceModelConfig config;
	const InputConfig input;

	results.push_back(measure("force model (input vector + 5 components)", [&](int p_n) {
		const Vec3 position{ 0.03 + 1e-6 * p_n, -0.02, 0.01 };
		const Vec3 i = input_vector(position, 0.1, input.dead_zone);
		g_sink = g_sink + compute_forces(frame, i, config).continuous.x;
	}));
	// The same with the paper's normalised sum (the default above is per_contact).
	ForceModelConfig paper = config;
	paper.contact_model = ContactModel::PAPER_SUM;
	results.push_back(measure("force model, paper_sum contacts", [&](int p_n) {
		const Vec3 position{ 0.03 + 1e-6 * p_n, -0.02, 0.01 };
		const Vec3 i = input_vector(position, 0.1, input.dead_zone);
		g_sink = g_sink + compute_forces(frame, i, paper).continuous.x;
	}));

	SmoothingFilter filter;
	filter.configure(SmoothingConfig{}, 0.001);
	results.push_back(measure("smoothing filter (3 axes)", [&](int p_n) {
		g_sink = g_sink + filter.process({ 1.0 + 1e-6 * p_n, 0.5, 0.0 }).x;
	}));

	TransientBank bank;
	results.push_back(measure("transients (3 active)", [&](int p_n) {
		if (bank.active_count() < 3) {
			ImpactEvent event;
			event.direction = { 0.0, 1.0, 0.0 };
			event.speed_m_per_s = 3.0 + 1e-3 * p_n;
			bank.add(event, ImpactMaterial{}, 3.0);
		}
		g_sink = g_sink + bank.advance(0.001).y;
	}));

	HapticsSystem system;
	system.open_simulated_device();
	system.set_hand_target({ 0.03, -0.02, 0.0 });
	system.submit_frame(frame);
	results.push_back(measure("full tick, manual step (device, model, filter, safety, publish)", [&](int p_n) {
		if (p_n % 20 == 0) {
			system.submit_frame(frame); // 50 Hz at 1 kHz: keeps the watchdog quiet.
		}
		system.step(0.001);
		if (p_n % 100 == 0) {
			float telemetry[100 * 32];
			system.drain_telemetry(telemetry, 100);
		}
	}));
	g_sink = g_sink + system.forces().total.x;

	// Haptic Battle Pong: the simulation step alone (contact law, spin, a slow effect,
	// court, events), then the whole tick in pong mode, both with the ball resting in
	// contact on the device paddle: the contact branch every tick, the costliest steady case.
	PongSim pong;
	pong.set_input(pong_bench_input());
	pong.apply(pong_bench_command(PongCommandType::SET_BALL));
	HandSample pong_hand;
	pong_hand.velocity_m_per_s = { 0.05, 0.0, 0.0 }; // A small brush: spin induction does work.
	uint64_t pong_ticks = 0;
	uint64_t pong_contacts = 0;
	MicroResult sim_result = measure("", [&](int p_n) {
		if (p_n == 0 && !pong.effects().running(PongEffectKind::SLOW)) {
			pong.apply(pong_bench_command(PongCommandType::EFFECT, PongEffectKind::SLOW));
		}
		pong.step(0.001, &pong_hand);
		PongEvent event;
		while (pong.events().pop(event)) {
		}
		++pong_ticks;
		pong_contacts += pong.contact(0).touching ? 1 : 0;
		g_sink = g_sink + pong.hand_forces().contact.y;
	});
	sim_result.name = with_contact_share("pong sim step alone, ball on the paddle", pong_contacts, pong_ticks);
	results.push_back(sim_result);

	HapticsSystem pong_engine;
	pong_engine.open_simulated_device();
	pong_engine.set_hand_target({ 0.0, 0.0, 0.0 });
	RenderConfig pong_config = pong_engine.config();
	pong_config.servo.render_mode = RenderMode::PONG;
	pong_engine.configure(pong_config);
	PongPort pong_port(pong_engine.renderers().pong.channels);
	pong_port.set_input(pong_bench_input());
	pong_port.push_command(pong_bench_command(PongCommandType::SET_BALL));
	for (int k = 0; k < 2000; ++k) { // Let the ball settle onto the paddle.
		if (k % 20 == 0) {
			pong_port.set_input(pong_bench_input());
		}
		pong_engine.step(0.001);
	}
	pong_ticks = 0;
	pong_contacts = 0;
	PongEvent events[16];
	MicroResult tick_result = measure("", [&](int p_n) {
		if (p_n % 20 == 0) {
			pong_port.set_input(pong_bench_input()); // 50 Hz: the watchdog's heartbeat.
		}
		pong_engine.step(0.001);
		if (p_n % 100 == 0) { // As often as the movement tick above drains: same overhead.
			float telemetry[100 * 32];
			pong_engine.drain_telemetry(telemetry, 100);
			pong_port.drain_events(events, 16);
			++pong_ticks; // Sampled here, not every tick: reading the output costs too.
			pong_contacts += (pong_engine.output().flags & TELEMETRY_FLAG_PADDLE_CONTACT) != 0 ? 1 : 0;
		}
	});
	tick_result.name = with_contact_share("full tick, manual step, pong mode, ball on the paddle", pong_contacts, pong_ticks);
	results.push_back(tick_result);
	g_sink = g_sink + pong_engine.forces().total.x;

	// The same tick in constraint mode: finite proxy against 10 000 walls, at 1 kHz.
	HapticsSystem maze_engine;
	SimulatedDeviceConfig hand;
	hand.rigid_hand = true;
	maze_engine.open_simulated_device(hand);
	const std::vector<Segment2> walls = haptics::test::perfect_maze(99, 10.0, 2024);
	MazeMapping mapping;
	mapping.maze_max = { 990.0, 990.0 };
	ConstraintPort(maze_engine.renderers().constraint.channels).set_geometry(walls.data(), walls.size(), mapping);
	ConstraintConfig constraint;
	constraint.proxy_radius = 3.0;
	RenderConfig maze_config = maze_engine.config();
	maze_config.constraint = constraint;
	maze_config.servo.render_mode = RenderMode::CONSTRAINT;
	maze_engine.configure(maze_config);
	int tick = 0;
	results.push_back(measure("full tick, manual step, constraint mode, 10 000 walls", [&](int p_n) {
		if (p_n % 20 == 0) {
			maze_engine.submit_frame(Frame{});
			const double t = 0.001 * tick;
			maze_engine.set_hand_target({ 0.065 * std::sin(2.3 * t), 0.065 * std::sin(3.3 * t + 0.4), 0.0 });
		}
		++tick;
		maze_engine.step(0.001);
		if (p_n % 100 == 0) {
			float telemetry[100 * 32];
			maze_engine.drain_telemetry(telemetry, 100);
		}
	}));
	g_sink = g_sink + maze_engine.forces().total.x;
	return results;
}

} // namespace haptics::bench
