#pragma once

// Pooling the rounds of one measurement: every tick of every round goes into one histogram of
// wake latency (1 us bins, as the servo's own: ServoStatsRecorder::LATENCY_BINS), whose
// percentiles are the row's figures. A p99.9 taken per round and then medianed is the few
// worst ticks of each short round, and swung by 2-8x between runs; pooled, it rests on every
// round's tail at once. How sure it is comes from the rounds themselves: the pooled p99.9 of
// the rounds drawn again with replacement (a bootstrap), whose central 95 % is the interval.

#include <cstdint>
#include <vector>

namespace haptics::bench {

// One round's latency: its bins' counts, and its exact maximum in seconds.
struct RoundBins {
	std::vector<uint32_t> bins;
	double max_s = 0.0;
};

struct PooledLatency {
	uint64_t count = 0;
	double p50 = 0.0, p99 = 0.0, p999 = 0.0, max = 0.0; // seconds
	double p999_low = 0.0, p999_high = 0.0; // The 95 % interval of p99.9 over the rounds.
};

// The bins' p_quantile (the centre of the bin holding that rank, as Histogram::percentile),
// capped at p_max_s; 0 when empty.
double bins_percentile(const std::vector<uint64_t> &p_bins, double p_quantile, double p_max_s);

// Pools p_rounds (each at least one tick); p_resamples draws of the rounds for the interval
// (a fixed seed: the same rounds give the same interval).
PooledLatency pool_rounds(const std::vector<const RoundBins *> &p_rounds, int p_resamples = 1000);

} // namespace haptics::bench
