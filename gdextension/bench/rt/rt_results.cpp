#include "rt_results.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

namespace haptics::bench {

Distribution from_stats_latency(const ServoStats &p_stats) {
	return { true, p_stats.latency_p50_s, p_stats.latency_p99_s, p_stats.latency_p999_s, p_stats.latency_max_s, p_stats.ticks };
}

Distribution from_stats_jitter(const ServoStats &p_stats) {
	return { true, p_stats.jitter_p50_s, p_stats.jitter_p99_s, p_stats.jitter_p999_s, p_stats.jitter_max_s,
		p_stats.ticks > 0 ? p_stats.ticks - 1 : 0 };
}

double rate_error_percent(const ServoStats &p_stats) {
	return p_stats.nominal_rate_hz > 0.0
			? 100.0 * std::abs(p_stats.achieved_rate_hz - p_stats.nominal_rate_hz) / p_stats.nominal_rate_hz
			: 0.0;
}

double median(std::vector<double> p_values) {
	if (p_values.empty()) {
		return 0.0;
	}
	std::sort(p_values.begin(), p_values.end());
	const size_t n = p_values.size();
	return n % 2 ? p_values[n / 2] : 0.5 * (p_values[n / 2 - 1] + p_values[n / 2]);
}

Distribution combine_distributions(const std::vector<const Distribution *> &p_rounds) {
	Distribution combined;
	std::vector<double> p50, p99, p999;
	for (const Distribution *d : p_rounds) {
		p50.push_back(d->p50);
		p99.push_back(d->p99);
		p999.push_back(d->p999);
		combined.max = std::max(combined.max, d->max);
		combined.count += d->count;
	}
	combined.measured = !p_rounds.empty();
	combined.p50 = median(p50);
	combined.p99 = median(p99);
	combined.p999 = median(p999);
	return combined;
}

CpuTimes read_cpu_times() {
	CpuTimes times;
	std::ifstream stat("/proc/stat");
	std::string cpu;
	unsigned long long field[8] = {};
	stat >> cpu;
	for (unsigned long long &value : field) {
		stat >> value;
	}
	for (const unsigned long long value : field) {
		times.total += value;
	}
	times.steal = field[7];
	return times;
}

double steal_percent(const CpuTimes &p_before, const CpuTimes &p_after) {
	const unsigned long long total = p_after.total - p_before.total;
	return total > 0 ? 100.0 * static_cast<double>(p_after.steal - p_before.steal) / static_cast<double>(total) : 0.0;
}

ToolResult combine(const std::vector<ToolResult> &p_rounds) {
	ToolResult combined;
	std::vector<const Distribution *> latency, jitter;
	std::vector<double> rate_error, cpu, steal;
	for (const ToolResult &round : p_rounds) {
		if (!round.measured) {
			continue;
		}
		latency.push_back(&round.latency);
		jitter.push_back(&round.jitter);
		rate_error.push_back(round.rate_error_percent);
		cpu.push_back(round.cpu_fraction);
		steal.push_back(round.steal_percent);
		const uint64_t late = combined.stats.late_ticks + round.stats.late_ticks;
		const uint64_t missed = combined.stats.missed_deadlines + round.stats.missed_deadlines;
		const uint64_t ticks = combined.stats.ticks + round.stats.ticks;
		combined.stats = round.stats;
		combined.stats.late_ticks = late;
		combined.stats.missed_deadlines = missed;
		combined.stats.ticks = ticks;
		combined.worst_rate_error_percent = std::max(combined.worst_rate_error_percent, round.rate_error_percent);
	}
	if (latency.empty()) {
		combined.why_not = p_rounds.empty() ? "not run" : p_rounds.front().why_not;
		return combined;
	}
	combined.measured = true;
	combined.rounds = static_cast<int>(latency.size());
	combined.latency = combine_distributions(latency);
	std::vector<const RoundBins *> bins;
	for (const ToolResult &round : p_rounds) {
		if (round.measured && !round.latency_bins.bins.empty()) {
			bins.push_back(&round.latency_bins);
		}
	}
	if (bins.size() == latency.size()) {
		const PooledLatency pooled = pool_rounds(bins);
		combined.latency = { true, pooled.p50, pooled.p99, pooled.p999, pooled.max, pooled.count, true, pooled.p999_low,
			pooled.p999_high };
	}
	combined.jitter = combine_distributions(jitter);
	combined.rate_error_percent = median(rate_error);
	combined.cpu_fraction = median(cpu);
	combined.steal_percent = median(steal);
	return combined;
}

} // namespace haptics::bench
