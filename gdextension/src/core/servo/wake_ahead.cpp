#include "core/servo/wake_ahead.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace haptics {

int64_t wake_ahead_cap_ns(double p_rate_hz, int64_t p_rttime_us) {
	int64_t cap = std::min<int64_t>(WAKE_AHEAD_MAX_NS, std::llround(1e9 / p_rate_hz) / 2);
	if (p_rttime_us > 0) {
		cap = std::min<int64_t>(cap, p_rttime_us * 1000 / 2);
	}
	return std::max<int64_t>(cap, 0);
}

void WakeAhead::reset(int64_t p_initial_ns, int64_t p_cap_ns) {
	cap_ns_ = std::max<int64_t>(p_cap_ns, 0);
	floor_ns_ = std::min<int64_t>(WAKE_AHEAD_MIN_NS, cap_ns_);
	ahead_ns_ = std::clamp<int64_t>(p_initial_ns, floor_ns_, cap_ns_);
	seen_ = 0;
	next_ = 0;
	std::fill(std::begin(ring_), std::end(ring_), uint16_t{ 0 });
	std::fill(std::begin(counts_), std::end(counts_), uint16_t{ 0 });
}

bool WakeAhead::observe(int64_t p_slept_at_ns, int64_t p_target_ns, int64_t p_woke_ns) {
	if (p_slept_at_ns >= p_target_ns) {
		return false;
	}
	const int64_t late_ns = std::max<int64_t>(p_woke_ns - p_target_ns, 0);
	const auto bin = static_cast<uint16_t>(std::min<int64_t>(late_ns / BIN_NS, static_cast<int64_t>(BINS - 1)));
	if (seen_ >= WAKE_AHEAD_WINDOW) {
		--counts_[ring_[next_]];
	}
	ring_[next_] = bin;
	++counts_[bin];
	next_ = (next_ + 1) % WAKE_AHEAD_WINDOW;
	++seen_;
	return seen_ >= WAKE_AHEAD_WINDOW && seen_ % UPDATE_EVERY == 0 && update();
}

bool WakeAhead::update() {
	// Wake-ups later than the largest wake-ahead (the last bin) are stalls no spin covers:
	// spinning for them costs a core and saves nothing, so the quantile is of the others.
	const uint32_t coverable = static_cast<uint32_t>(WAKE_AHEAD_WINDOW) - counts_[BINS - 1];
	int64_t wanted = floor_ns_;
	if (coverable > 0) {
		// The smallest bin at or below which WAKE_AHEAD_QUANTILE of them lies, found from the
		// top: the tail is short, so the scan stops early.
		const auto rank = static_cast<uint32_t>(std::ceil(WAKE_AHEAD_QUANTILE * static_cast<double>(coverable)));
		uint32_t above = 0;
		size_t bin = BINS - 2;
		while (bin > 0 && coverable - above - counts_[bin] >= rank) {
			above += counts_[bin];
			--bin;
		}
		// The bin's upper edge: every wake-up in it is covered.
		wanted = std::clamp<int64_t>((static_cast<int64_t>(bin) + 1) * BIN_NS, floor_ns_, cap_ns_);
	}
	const bool changed = wanted != ahead_ns_;
	ahead_ns_ = wanted;
	return changed;
}

} // namespace haptics
