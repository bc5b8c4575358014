#include "rt_pool.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace haptics::bench {

namespace {

constexpr double BIN_S = 1e-6;

void add_round(std::vector<uint64_t> &r_pool, const RoundBins &p_round) {
	if (r_pool.size() < p_round.bins.size()) {
		r_pool.resize(p_round.bins.size(), 0);
	}
	for (size_t b = 0; b < p_round.bins.size(); ++b) {
		r_pool[b] += p_round.bins[b];
	}
}

} // namespace

double bins_percentile(const std::vector<uint64_t> &p_bins, double p_quantile, double p_max_s) {
	uint64_t total = 0;
	for (const uint64_t count : p_bins) {
		total += count;
	}
	if (total == 0) {
		return 0.0;
	}
	const double q = std::clamp(p_quantile, 0.0, 1.0);
	const uint64_t rank = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(q * static_cast<double>(total))));
	uint64_t seen = 0;
	for (size_t b = 0; b < p_bins.size(); ++b) {
		seen += p_bins[b];
		if (seen >= rank) {
			return std::min((static_cast<double>(b) + 0.5) * BIN_S, p_max_s);
		}
	}
	return p_max_s;
}

PooledLatency pool_rounds(const std::vector<const RoundBins *> &p_rounds, int p_resamples) {
	PooledLatency pooled;
	std::vector<uint64_t> all;
	for (const RoundBins *round : p_rounds) {
		add_round(all, *round);
		pooled.max = std::max(pooled.max, round->max_s);
	}
	for (const uint64_t count : all) {
		pooled.count += count;
	}
	pooled.p50 = bins_percentile(all, 0.50, pooled.max);
	pooled.p99 = bins_percentile(all, 0.99, pooled.max);
	pooled.p999 = bins_percentile(all, 0.999, pooled.max);
	pooled.p999_low = pooled.p999_high = pooled.p999;
	if (p_rounds.size() < 2 || p_resamples < 1) {
		return pooled;
	}
	std::mt19937 random(39);
	std::uniform_int_distribution<size_t> pick(0, p_rounds.size() - 1);
	std::vector<double> drawn;
	std::vector<uint64_t> sample;
	for (int r = 0; r < p_resamples; ++r) {
		std::fill(sample.begin(), sample.end(), 0);
		double max_s = 0.0;
		for (size_t k = 0; k < p_rounds.size(); ++k) {
			const RoundBins &round = *p_rounds[pick(random)];
			add_round(sample, round);
			max_s = std::max(max_s, round.max_s);
		}
		drawn.push_back(bins_percentile(sample, 0.999, max_s));
	}
	std::sort(drawn.begin(), drawn.end());
	const auto at = [&](double p_q) { return drawn[static_cast<size_t>(p_q * static_cast<double>(drawn.size() - 1))]; };
	pooled.p999_low = at(0.025);
	pooled.p999_high = at(0.975);
	return pooled;
}

} // namespace haptics::bench
