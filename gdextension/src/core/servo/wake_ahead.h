#pragma once

// The servo's learned wake-ahead: where the thread has real time but cannot hold the CPU's
// wake-up latency (an ordinary user without the udev rule), an idle core sleeps deeper and
// wakes later, by an amount that depends on the machine. So the thread wakes early by what its
// own recent wake-ups cost (WAKE_AHEAD_QUANTILE of their lateness over the last
// WAKE_AHEAD_WINDOW sleeps) and spins the rest of the way to its deadline. An idle machine, whose
// wake-ups are slow, is also one whose CPU is free to spin; under load the wake-ups come
// promptly and the spin shrinks to WAKE_AHEAD_MIN_NS. Wake-ups later than WAKE_AHEAD_MAX_NS are
// stalls no spin covers (a loaded machine's): they are left out of the quantile.
//
// Pure logic: the loop tells it when each sleep began, what it asked for and when it woke.
// Fixed-size (a ring of the window's bins and a histogram of 1 us bins): no allocation, and
// O(1) per wake-up but for a scan of the histogram every UPDATE_EVERY wake-ups.

#include "core/servo/servo.gen.h"

#include <cstddef>
#include <cstdint>

namespace haptics {

// The most a wake-ahead may be at p_rate_hz for a thread whose RLIMIT_RTTIME is p_rttime_us
// (0: none): WAKE_AHEAD_MAX_NS, half a period (the tick keeps the other half), and half the
// CPU time a real-time thread may run without sleeping (the tick must fit in the rest).
int64_t wake_ahead_cap_ns(double p_rate_hz, int64_t p_rttime_us);

class WakeAhead {
public:
	static constexpr int64_t BIN_NS = 1000;
	// Lateness from 0 to WAKE_AHEAD_MAX_NS in 1 us bins; the last holds everything beyond.
	static constexpr size_t BINS = static_cast<size_t>(WAKE_AHEAD_MAX_NS / BIN_NS) + 1;
	static constexpr size_t UPDATE_EVERY = 64;

	// Starts over: p_initial_ns until a whole window has been seen, then what it learns,
	// within [min(WAKE_AHEAD_MIN_NS, p_cap_ns), p_cap_ns].
	void reset(int64_t p_initial_ns, int64_t p_cap_ns);

	// How early to wake before the next deadline.
	int64_t ahead_ns() const { return ahead_ns_; }
	// Whether a whole window has been seen (ahead_ns() is learned, not the initial value).
	bool learned() const { return seen_ >= WAKE_AHEAD_WINDOW; }

	// A sleep that began at p_slept_at_ns, asked to wake at p_target_ns, woke at p_woke_ns.
	// Returns whether ahead_ns() changed. A sleep asked for a time already past (a tick that
	// overran) measures the overrun, not a wake-up: it is not counted.
	bool observe(int64_t p_slept_at_ns, int64_t p_target_ns, int64_t p_woke_ns);

private:
	bool update();

	int64_t ahead_ns_ = 0;
	int64_t floor_ns_ = 0;
	int64_t cap_ns_ = 0;
	uint64_t seen_ = 0;
	size_t next_ = 0; // The ring's oldest slot, overwritten next.
	uint16_t ring_[WAKE_AHEAD_WINDOW] = {};
	uint16_t counts_[BINS] = {};
};

static_assert(WAKE_AHEAD_WINDOW <= UINT16_MAX, "a bin's count is 16 bits");
static_assert(WakeAhead::BINS <= UINT16_MAX, "the ring holds bin indices in 16 bits");

} // namespace haptics
