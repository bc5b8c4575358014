#pragma once

// End-to-end latency on the simulated device, in servo ticks: the hand target steps, and we
// count the ticks until the rendered force first changes and until it has made 90 % of its
// change, in movement mode (pushing into a contact) and constraint mode (pushing into a wall),
// with the default compliant hand and with a rigid one (the software's own share). The
// shipped configuration throughout (smoothing, slew limit); manual step(), so it is exact.

#include <string>
#include <vector>

namespace haptics::bench {

struct LatencyResult {
	std::string mode; // "movement" or "constraint"
	std::string hand; // "compliant" or "rigid"
	int first_change_ticks = -1; // -1: never changed
	int settle_90_ticks = -1;
	double force_before_n = 0.0;
	double force_after_n = 0.0;
};

std::vector<LatencyResult> measure_latencies();
void print_latencies(const std::vector<LatencyResult> &p_results, double p_rate_hz);

} // namespace haptics::bench
