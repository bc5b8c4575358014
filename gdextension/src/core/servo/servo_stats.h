#pragma once

// Loop statistics recorded inside the tick without allocation or locks: fixed-size
// histograms whose bins are relaxed atomics written by the servo thread alone (a plain load
// + store, no read-modify-write) and read by any thread. A reader running while the servo
// ticks may see counts from slightly different ticks in different bins; after stop() the
// figures are exact. Percentiles are computed by the reader, never in the tick.

#include "core/base/realtime.h"
#include "core/servo/servo_stats.gen.h"

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace haptics {

// Values in seconds, linear bins of BIN_WIDTH; larger values land in the last bin (the
// exact maximum is kept separately).
template <size_t BINS>
class Histogram {
public:
	explicit Histogram(double p_bin_width_s) :
			bin_width_s_(p_bin_width_s) {}

	void reset();
	void record(double p_value_s); // Single writer.

	uint64_t count() const { return count_.load(std::memory_order_relaxed); }
	double mean() const;
	double max() const { return max_.load(std::memory_order_relaxed); }
	// p_quantile in [0, 1]: the centre of the bin holding that rank, capped at max(); 0
	// when empty.
	double percentile(double p_quantile) const;
	// Copies up to p_capacity bins' counts into r_bins; returns BINS.
	size_t copy_bins(uint32_t *r_bins, size_t p_capacity) const;

private:
	const double bin_width_s_;
	std::atomic<uint32_t> bins_[BINS] = {};
	std::atomic<uint64_t> count_{ 0 };
	std::atomic<double> sum_{ 0.0 };
	std::atomic<double> max_{ 0.0 };
};

extern template class Histogram<20000>;
extern template class Histogram<10000>;

class ServoStatsRecorder {
public:
	static constexpr size_t LATENCY_BINS = 20000; // 1 us each: 0-20 ms.

	ServoStatsRecorder();

	// Not concurrent with record_tick (call before the thread starts).
	void reset(double p_nominal_rate_hz);
	// Single writer. p_period_s < 0 for the first tick of a session (no period yet).
	void record_tick(double p_now_s, double p_period_s, double p_lateness_s, double p_cost_s);
	void record_missed(uint64_t p_count);
	// The servo thread's CPU time (thread_cpu_time_ns) at p_now_s; the first call of a
	// session is the baseline.
	void record_thread_cpu(double p_now_s, double p_cpu_s);

	// Fills the loop-timing fields of r_stats (rate, period, jitter, late, cost, ticks).
	void fill(ServoStats &r_stats) const;
	// The wake-up latency histogram's bins (1 us each), as Histogram::copy_bins.
	size_t latency_bins(uint32_t *r_bins, size_t p_capacity) const { return latency_.copy_bins(r_bins, p_capacity); }

private:
	static constexpr double PERIOD_BIN_S = 1e-6;
	static constexpr double COST_BIN_S = 10e-9;

	std::atomic<double> nominal_rate_hz_{ 0.0 };
	std::atomic<double> first_tick_s_{ 0.0 };
	std::atomic<double> last_tick_s_{ 0.0 };
	std::atomic<uint64_t> ticks_{ 0 };
	std::atomic<uint64_t> late_{ 0 };
	std::atomic<uint64_t> missed_{ 0 };
	Histogram<20000> period_{ PERIOD_BIN_S }; // 0-20 ms
	Histogram<20000> jitter_{ PERIOD_BIN_S }; // 0-20 ms
	Histogram<LATENCY_BINS> latency_{ PERIOD_BIN_S };
	std::atomic<double> cpu_first_now_s_{ -1.0 };
	std::atomic<double> cpu_first_s_{ 0.0 };
	std::atomic<double> cpu_last_now_s_{ 0.0 };
	std::atomic<double> cpu_last_s_{ 0.0 };
	Histogram<10000> cost_{ COST_BIN_S }; // 0-100 us
};

} // namespace haptics
