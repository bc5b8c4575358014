#pragma once

// Shared pieces of the servo benchmark (haptics_bench): results, the micro-benchmarks, and
// the table/JSON report. Not part of the product.

#include "core/servo/servo_stats.h"
#include "renderers/constraint/swept_disc.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace haptics::bench {

struct LoopResult {
	std::string name; // "deadline" or "naive"
	ServoStats stats;
	std::vector<uint32_t> latency_bins; // The wake latency's histogram (HapticsSystem::latency_bins).
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

// One maze size and device path of the proxy benchmark (proxy_bench.cpp).
struct ProxyBenchResult {
	size_t segments = 0;
	std::string path; // "sweep" or "local"
	int32_t grid_columns = 0;
	int32_t grid_rows = 0;
	double grid_p50_ns = 0.0; // Per proxy update.
	double grid_p99_ns = 0.0;
	double grid_max_ns = 0.0;
	double brute_p50_ns = 0.0;
	double brute_p99_ns = 0.0;
	double brute_max_ns = 0.0;
	double mean_sweeps = 0.0; // Sweeps (continuous collision casts) per update.
	double contact_fraction = 0.0; // Updates that ended against a wall.
	bool identical = false; // Grid and brute force gave the same proxy path, bit for bit.
};

// Tick-cost micro-benchmarks: force model alone, filter, transients, the Pong simulation's
// step, full manual tick (movement, pong and constraint mode).
std::vector<MicroResult> run_micro_benchmarks();
// Proxy update cost for 100 / 1 000 / 10 000 walls, grid vs brute force.
std::vector<ProxyBenchResult> run_proxy_benchmarks();

void print_report(const LoopResult &p_deadline, const LoopResult &p_naive, const std::vector<MicroResult> &p_micro);
void print_proxy_report(const std::vector<ProxyBenchResult> &p_proxy);
// Returns false (and prints why) if the file cannot be written. Without loops (null), only
// the proxy section is written (haptics_bench --proxy-only).
bool write_json(const std::string &p_path, const LoopResult *p_deadline, const LoopResult *p_naive,
		const std::vector<MicroResult> &p_micro, const std::vector<ProxyBenchResult> &p_proxy);

} // namespace haptics::bench
