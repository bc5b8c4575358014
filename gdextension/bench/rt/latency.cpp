#include "latency.h"

#include "renderers/constraint/constraint_port.h"
#include "system/haptics_system.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace haptics::bench {

namespace {

constexpr double DT = 0.001;
constexpr int WARM_UP_TICKS = 2000; // Past the start-up ramp.
constexpr int AFTER_TICKS = 2000;
constexpr int FRAME_TICKS = 20; // The game's 50 Hz.

void require(const Status &p_status, const char *p_what) {
	if (!p_status) {
		std::fprintf(stderr, "latency bench: %s: %s\n", p_what, p_status.message());
		std::exit(2);
	}
}

LatencyResult measure(bool p_constraint, bool p_rigid) {
	LatencyResult result;
	result.mode = p_constraint ? "constraint" : "movement";
	result.hand = p_rigid ? "rigid" : "compliant";
	HapticsSystem system;
	SimulatedDeviceConfig device;
	device.rigid_hand = p_rigid;
	require(system.open_simulated_device(device), "open");
	Frame frame;
	Vec3 step_to;
	if (p_constraint) {
		// One vertical wall at maze x = 120; the hand starts at maze x = 90 (the centre of a
		// 180-unit maze on a 0.08 m workspace) and steps to x = 130, past the wall.
		MazeMapping mapping;
		mapping.maze_min = { 0.0, 0.0 };
		mapping.maze_max = { 180.0, 180.0 };
		mapping.workspace_half_extent_m = 0.08;
		const Segment2 wall{ { 120.0, 0.0 }, { 120.0, 180.0 } };
		require(ConstraintPort(system.renderers().constraint.channels).set_geometry(&wall, 1, mapping), "geometry");
		RenderConfig config = system.config();
		config.servo.render_mode = RenderMode::CONSTRAINT;
		require(system.configure(config), "constraint mode");
		step_to = { 40.0 * 0.16 / (180.0 * std::sqrt(2.0)), 0.0, 0.0 };
	} else {
		// A wall on the player's right (normal pointing left, towards the player); the hand
		// steps right, into it.
		add_contact(frame, { -1.0, 0.0, 0.0 });
		step_to = { 0.05, 0.0, 0.0 };
	}
	require(system.set_hand_target({ 0.0, 0.0, 0.0 }), "hand");
	uint64_t sequence = 0;
	const auto tick = [&](int p_index) {
		if (p_index % FRAME_TICKS == 0) {
			frame.sequence = ++sequence;
			require(system.submit_frame(frame), "frame");
		}
		require(system.step(DT), "step");
		return system.forces().total;
	};
	for (int k = 0; k < WARM_UP_TICKS; ++k) {
		tick(k);
	}
	const Vec3 before = system.forces().total;
	require(system.set_hand_target(step_to), "hand step");
	std::vector<Vec3> after;
	after.reserve(AFTER_TICKS);
	for (int k = 0; k < AFTER_TICKS; ++k) {
		after.push_back(tick(WARM_UP_TICKS + k));
	}
	const Vec3 final_force = after.back();
	const double change = length(final_force - before);
	result.force_before_n = length(before);
	result.force_after_n = length(final_force);
	for (int k = 0; k < AFTER_TICKS; ++k) {
		const double moved = length(after[static_cast<size_t>(k)] - before);
		if (result.first_change_ticks < 0 && moved > 1e-9) {
			result.first_change_ticks = k + 1;
		}
		if (result.settle_90_ticks < 0 && change > 0.0 && moved >= 0.9 * change) {
			result.settle_90_ticks = k + 1;
		}
	}
	return result;
}

} // namespace

std::vector<LatencyResult> measure_latencies() {
	std::vector<LatencyResult> results;
	for (const bool constraint : { false, true }) {
		for (const bool rigid : { true, false }) {
			results.push_back(measure(constraint, rigid));
		}
	}
	return results;
}

void print_latencies(const std::vector<LatencyResult> &p_results, double p_rate_hz) {
	std::printf("\nEnd-to-end latency, simulated device, shipped configuration: hand target stepped, ticks (at %.0f Hz) "
				"until the rendered force changes\n",
			p_rate_hz);
	std::printf("  %-11s %-10s %14s %14s %12s %12s\n", "mode", "hand", "first change", "90 % of step", "|F| before",
			"|F| after");
	for (const LatencyResult &r : p_results) {
		std::printf("  %-11s %-10s %8d ticks %8d ticks %10.3f N %10.3f N\n", r.mode.c_str(), r.hand.c_str(),
				r.first_change_ticks, r.settle_90_ticks, r.force_before_n, r.force_after_n);
	}
}

} // namespace haptics::bench
