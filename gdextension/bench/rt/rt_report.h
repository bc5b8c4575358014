#pragma once

// haptics_rt_bench's report: each condition printed next to cyclictest with the ratio to the
// goal, and everything written as JSON.

#include "latency.h"
#include "rt_results.h"

#include <string>
#include <vector>

namespace haptics::bench {

// Servo / cyclictest at p99 and p99.9, and the servo's rate error.
inline constexpr double GOAL_RATIO = 1.25;
inline constexpr double RATE_GOAL_PERCENT = 0.05;

void print_condition(const ConditionResult &p_result);
void print_techniques(const ConditionResult &p_result);
bool write_json(const std::string &p_path, const std::vector<LatencyResult> &p_latencies,
		const std::vector<ConditionResult> &p_results);

} // namespace haptics::bench
