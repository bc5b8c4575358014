#pragma once

// Shared pieces of the servo benchmark (haptics_bench): results, the micro-benchmarks, and
// the table/JSON report. Not part of the product.

#include "core/servo_stats.h"

#include <string>
#include <vector>

namespace haptics::bench {

struct LoopResult {
	std::string name; // "deadline" or "naive"
	ServoStats stats;
	double duration_s = 0.0;
	uint64_t frames_submitted = 0;
	uint64_t impacts_pushed = 0;
	uint64_t telemetry_drained = 0;
};

struct MicroResult {
	std::string name;
	double median_ns = 0.0; // Per call, median over batches.
	double p99_ns = 0.0;
};

// Tick-cost micro-benchmarks: force model alone, filter, transients, full manual tick.
std::vector<MicroResult> run_micro_benchmarks();

void print_report(const LoopResult &p_deadline, const LoopResult &p_naive, const std::vector<MicroResult> &p_micro);
// Returns false (and prints why) if the file cannot be written.
bool write_json(const std::string &p_path, const LoopResult &p_deadline, const LoopResult &p_naive,
		const std::vector<MicroResult> &p_micro);

} // namespace haptics::bench
