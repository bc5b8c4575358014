#include "core/servo/servo_stats.h"

#include <algorithm>
#include <cmath>

namespace haptics {

namespace {

// Single-writer increment: no read-modify-write needed, so no lock prefix in the tick.
template <typename T>
void bump(std::atomic<T> &r_counter, T p_amount = 1) {
	r_counter.store(r_counter.load(std::memory_order_relaxed) + p_amount, std::memory_order_relaxed);
}

} // namespace

template <size_t BINS>
void Histogram<BINS>::reset() {
	for (std::atomic<uint32_t> &bin : bins_) {
		bin.store(0, std::memory_order_relaxed);
	}
	count_.store(0, std::memory_order_relaxed);
	sum_.store(0.0, std::memory_order_relaxed);
	max_.store(0.0, std::memory_order_relaxed);
}

template <size_t BINS>
void Histogram<BINS>::record(double p_value_s) {
	const double value = std::max(0.0, p_value_s);
	const double index = std::floor(value / bin_width_s_);
	const size_t bin = index >= static_cast<double>(BINS - 1) ? BINS - 1 : static_cast<size_t>(index);
	bump(bins_[bin], uint32_t{ 1 });
	bump(count_, uint64_t{ 1 });
	bump(sum_, value);
	if (value > max_.load(std::memory_order_relaxed)) {
		max_.store(value, std::memory_order_relaxed);
	}
}

template <size_t BINS>
double Histogram<BINS>::mean() const {
	const uint64_t n = count();
	return n ? sum_.load(std::memory_order_relaxed) / static_cast<double>(n) : 0.0;
}

template <size_t BINS>
double Histogram<BINS>::percentile(double p_quantile) const {
	uint64_t total = 0;
	for (const std::atomic<uint32_t> &bin : bins_) {
		total += bin.load(std::memory_order_relaxed);
	}
	if (total == 0) {
		return 0.0;
	}
	const double q = std::clamp(p_quantile, 0.0, 1.0);
	const uint64_t rank = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(q * static_cast<double>(total))));
	uint64_t seen = 0;
	for (size_t b = 0; b < BINS; ++b) {
		seen += bins_[b].load(std::memory_order_relaxed);
		if (seen >= rank) {
			return std::min((static_cast<double>(b) + 0.5) * bin_width_s_, max());
		}
	}
	return max();
}

template <size_t BINS>
size_t Histogram<BINS>::copy_bins(uint32_t *r_bins, size_t p_capacity) const {
	for (size_t b = 0; b < BINS && b < p_capacity; ++b) {
		r_bins[b] = bins_[b].load(std::memory_order_relaxed);
	}
	return BINS;
}

template class Histogram<20000>;
template class Histogram<10000>;

ServoStatsRecorder::ServoStatsRecorder() = default;

void ServoStatsRecorder::reset(double p_nominal_rate_hz) {
	nominal_rate_hz_.store(p_nominal_rate_hz, std::memory_order_relaxed);
	first_tick_s_.store(0.0, std::memory_order_relaxed);
	last_tick_s_.store(0.0, std::memory_order_relaxed);
	ticks_.store(0, std::memory_order_relaxed);
	late_.store(0, std::memory_order_relaxed);
	missed_.store(0, std::memory_order_relaxed);
	period_.reset();
	jitter_.reset();
	latency_.reset();
	cost_.reset();
	cpu_first_now_s_.store(-1.0, std::memory_order_relaxed);
	cpu_first_s_.store(0.0, std::memory_order_relaxed);
	cpu_last_now_s_.store(0.0, std::memory_order_relaxed);
	cpu_last_s_.store(0.0, std::memory_order_relaxed);
}

void ServoStatsRecorder::record_tick(double p_now_s, double p_period_s, double p_lateness_s, double p_cost_s) {
	const double nominal_period = 1.0 / nominal_rate_hz_.load(std::memory_order_relaxed);
	if (ticks_.load(std::memory_order_relaxed) == 0) {
		first_tick_s_.store(p_now_s, std::memory_order_relaxed);
	}
	last_tick_s_.store(p_now_s, std::memory_order_relaxed);
	bump(ticks_, uint64_t{ 1 });
	if (p_period_s >= 0.0) {
		period_.record(p_period_s);
		jitter_.record(std::abs(p_period_s - nominal_period));
	}
	latency_.record(p_lateness_s);
	if (p_lateness_s > 0.5 * nominal_period) {
		bump(late_, uint64_t{ 1 });
	}
	cost_.record(p_cost_s);
}

void ServoStatsRecorder::record_missed(uint64_t p_count) {
	bump(missed_, p_count);
}

void ServoStatsRecorder::record_thread_cpu(double p_now_s, double p_cpu_s) {
	if (cpu_first_now_s_.load(std::memory_order_relaxed) < 0.0) {
		cpu_first_s_.store(p_cpu_s, std::memory_order_relaxed);
		cpu_first_now_s_.store(p_now_s, std::memory_order_relaxed);
	}
	cpu_last_s_.store(p_cpu_s, std::memory_order_relaxed);
	cpu_last_now_s_.store(p_now_s, std::memory_order_relaxed);
}

void ServoStatsRecorder::fill(ServoStats &r_stats) const {
	r_stats.nominal_rate_hz = nominal_rate_hz_.load(std::memory_order_relaxed);
	r_stats.ticks = ticks_.load(std::memory_order_relaxed);
	const double span = last_tick_s_.load(std::memory_order_relaxed) - first_tick_s_.load(std::memory_order_relaxed);
	r_stats.achieved_rate_hz = r_stats.ticks > 1 && span > 0.0 ? static_cast<double>(r_stats.ticks - 1) / span : 0.0;
	r_stats.period_mean_s = period_.mean();
	r_stats.period_p50_s = period_.percentile(0.50);
	r_stats.period_p99_s = period_.percentile(0.99);
	r_stats.period_p999_s = period_.percentile(0.999);
	r_stats.period_max_s = period_.max();
	r_stats.jitter_p50_s = jitter_.percentile(0.50);
	r_stats.jitter_p99_s = jitter_.percentile(0.99);
	r_stats.jitter_p999_s = jitter_.percentile(0.999);
	r_stats.jitter_max_s = jitter_.max();
	r_stats.latency_p50_s = latency_.percentile(0.50);
	r_stats.latency_p99_s = latency_.percentile(0.99);
	r_stats.latency_p999_s = latency_.percentile(0.999);
	r_stats.latency_max_s = latency_.max();
	const double cpu_first_now = cpu_first_now_s_.load(std::memory_order_relaxed);
	const double cpu_wall = cpu_last_now_s_.load(std::memory_order_relaxed) - cpu_first_now;
	r_stats.thread_cpu_fraction = cpu_first_now >= 0.0 && cpu_wall > 0.0
			? (cpu_last_s_.load(std::memory_order_relaxed) - cpu_first_s_.load(std::memory_order_relaxed)) / cpu_wall
			: 0.0;
	r_stats.late_ticks = late_.load(std::memory_order_relaxed);
	r_stats.missed_deadlines = missed_.load(std::memory_order_relaxed);
	r_stats.tick_cost_p50_s = cost_.percentile(0.50);
	r_stats.tick_cost_p99_s = cost_.percentile(0.99);
	r_stats.tick_cost_max_s = cost_.max();
}

} // namespace haptics
