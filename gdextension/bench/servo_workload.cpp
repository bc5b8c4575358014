#include "servo_workload.h"

#include "core/base/realtime.h"
#include "core/servo/telemetry.h"
#include "system/haptics_system.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

namespace haptics::bench {

namespace {

// The game's side for one run: 50 Hz on absolute deadlines, like a physics tick.
void produce(HapticsSystem &r_system, double p_duration_s, LoopResult &r_result) {
	constexpr int64_t FRAME_NS = 20'000'000;
	std::vector<float> telemetry(512 * TELEMETRY_STRIDE);
	const int64_t begin = monotonic_now_ns();
	const int64_t end = begin + static_cast<int64_t>(p_duration_s * 1e9);
	int64_t deadline = begin;
	for (uint64_t frame_index = 0; deadline < end; ++frame_index) {
		const double phase = static_cast<double>(frame_index) * 0.05;
		Frame frame;
		frame.sequence = frame_index;
		frame.time_s = static_cast<double>(deadline - begin) * 1e-9;
		add_contact(frame, { 0.0, 1.0, 0.0 });
		add_contact(frame, { -std::cos(phase), 0.3, 0.0 }, ContactMaterial{ 2.5, 0.8 });
		add_resting(frame, { 0.0, -1.0, 0.0 }, 0.6);
		set_water(frame, (frame_index / 50) % 2 == 1, 0.4, 0.3);
		frame.velocity_m_per_s = { std::sin(phase), -0.2, 0.0 };
		r_system.submit_frame(frame);
		++r_result.frames_submitted;
		r_system.set_hand_target({ 0.06 * std::sin(phase * 0.7), -0.03 + 0.02 * std::cos(phase), 0.0 });
		if (frame_index % 5 == 0) {
			ImpactEvent event;
			event.direction = { 0.0, 1.0, 0.0 };
			event.speed_m_per_s = 2.0 + std::sin(phase);
			r_system.push_impact(event);
			++r_result.impacts_pushed;
		}
		r_result.telemetry_drained += r_system.drain_telemetry(telemetry.data(), 512);
		deadline += FRAME_NS;
		sleep_until_ns(deadline);
	}
}

} // namespace

LoopResult run_servo_workload(const char *p_name, const ServoOptions &p_options, double p_duration_s) {
	LoopResult result;
	result.name = p_name;
	result.duration_s = p_duration_s;
	HapticsSystem system;
	if (!system.open_simulated_device()) {
		std::fprintf(stderr, "cannot open the simulated device\n");
		std::exit(2);
	}
	const Status started = system.start(p_options);
	if (!started) {
		std::fprintf(stderr, "cannot start the servo: %s\n", started.message());
		std::exit(2);
	}
	// The producer is the only thread calling the engine while the servo runs.
	std::thread producer([&] { produce(system, p_duration_s, result); });
	producer.join();
	system.stop();
	result.stats = system.stats();
	result.latency_bins.resize(ServoStatsRecorder::LATENCY_BINS);
	system.latency_bins(result.latency_bins.data(), result.latency_bins.size());
	return result;
}

} // namespace haptics::bench
