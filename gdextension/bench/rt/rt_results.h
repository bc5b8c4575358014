#pragma once

// haptics_rt_bench's measurements: one measurement's distributions and figures
// (ToolResult), a condition's (ConditionResult), and how the rounds of one measurement
// combine into the figures printed (wake latency pooled over every tick of every round,
// rt_pool.h; the rest medians, the largest max).

#include "core/servo/servo_stats.h"
#include "rt_pool.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace haptics::bench {

inline constexpr double US = 1e6;

struct Distribution {
	bool measured = false;
	double p50 = 0.0, p99 = 0.0, p999 = 0.0, max = 0.0; // seconds
	uint64_t count = 0;
	bool pooled = false; // Every tick of every round in one histogram (else medians of rounds).
	double p999_low = 0.0, p999_high = 0.0; // Pooled: p99.9's 95 % interval over the rounds.
};

struct ToolResult {
	bool measured = false;
	double steal_percent = 0.0; // CPU time the hypervisor took while it ran.
	std::string why_not; // When not measured.
	Distribution latency;
	RoundBins latency_bins; // One round's; empty when not kept.
	Distribution jitter;
	double rate_error_percent = 0.0;
	double worst_rate_error_percent = 0.0; // Over the rounds.
	double cpu_fraction = 0.0;
	int rounds = 1;
	ServoStats stats; // Servo only.
};

struct ConditionResult {
	std::string name;
	bool measured = false;
	std::string why_not;
	std::string detail; // How the load was made.
	ToolResult servo;
	ToolResult cyclictest;
	int32_t cyclictest_priority = 0;
	std::vector<std::pair<std::string, ToolResult>> techniques;
};

// The machine's CPU time from /proc/stat's first line, in clock ticks: all of it, and the
// part the hypervisor gave to other guests (steal).
struct CpuTimes {
	unsigned long long total = 0;
	unsigned long long steal = 0;
};
CpuTimes read_cpu_times();
double steal_percent(const CpuTimes &p_before, const CpuTimes &p_after);

// From the servo's own statistics.
Distribution from_stats_latency(const ServoStats &p_stats);
Distribution from_stats_jitter(const ServoStats &p_stats);
double rate_error_percent(const ServoStats &p_stats);

double median(std::vector<double> p_values);
Distribution combine_distributions(const std::vector<const Distribution *> &p_rounds);
// The rounds of one measurement: the wake latency pooled when every round kept its bins;
// medians of the other percentiles, rate error and CPU share; the largest max; the last round's
// stats (what was granted) with the counters summed. Rounds that could not be measured are
// left out; when none could, the first one's reason is kept.
ToolResult combine(const std::vector<ToolResult> &p_rounds);

} // namespace haptics::bench
