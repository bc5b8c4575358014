// The learned wake-ahead (wake_ahead.h) against a scripted clock: each simulated sleep wakes
// as late as a script says, and the loop spins to its deadline from there, as the servo's does.
// What is checked is what the servo's ticks would see: how late they wake, and what it costs.

#include "core/servo/wake_ahead.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <functional>

using namespace haptics;

namespace {

constexpr int64_t PERIOD_NS = 1'000'000;
constexpr int64_t TICK_NS = 20'000; // What each simulated tick costs before it sleeps again.

// A 1 kHz loop whose every sleep wakes p_late_ns(k) after the time it asked for.
struct ScriptedLoop {
	WakeAhead wake_ahead;
	int64_t deadline_ns = PERIOD_NS;
	int64_t late_ticks = 0; // Ticks the spin did not cover: they woke after their deadline.
	int64_t spun_ns = 0;

	explicit ScriptedLoop(int64_t p_cap_ns = wake_ahead_cap_ns(1000.0, 0)) {
		wake_ahead.reset(UNHELD_SPIN_NS, p_cap_ns);
	}

	void run(int64_t p_ticks, const std::function<int64_t(int64_t)> &p_late_ns) {
		for (int64_t k = 0; k < p_ticks; ++k) {
			const int64_t slept_at = deadline_ns - PERIOD_NS + TICK_NS;
			const int64_t target = deadline_ns - wake_ahead.ahead_ns();
			const int64_t woke = target + p_late_ns(k);
			late_ticks += woke > deadline_ns ? 1 : 0;
			spun_ns += std::max<int64_t>(deadline_ns - woke, 0);
			wake_ahead.observe(slept_at, target, woke);
			deadline_ns += PERIOD_NS;
		}
	}
};

// Mostly p_usual_ns late, one wake-up in p_every p_rare_ns late.
std::function<int64_t(int64_t)> mostly(int64_t p_usual_ns, int64_t p_every, int64_t p_rare_ns) {
	return [=](int64_t p_k) { return p_k % p_every == p_every - 1 ? p_rare_ns : p_usual_ns + (p_k * 7919) % 5'000; };
}

} // namespace

TEST_CASE("wake-ahead: it spins the starting value until it has seen a whole window") {
	ScriptedLoop loop;
	loop.run(static_cast<int64_t>(WAKE_AHEAD_WINDOW) - 1, mostly(10'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.ahead_ns() == UNHELD_SPIN_NS);
	CHECK_FALSE(loop.wake_ahead.learned());
	loop.run(WakeAhead::UPDATE_EVERY, mostly(10'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.learned());
	CHECK(loop.wake_ahead.ahead_ns() < UNHELD_SPIN_NS);
}

TEST_CASE("wake-ahead: a machine whose wake-ups are prompt spins little") {
	ScriptedLoop loop;
	loop.run(3 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(2'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.ahead_ns() == WAKE_AHEAD_MIN_NS);
}

TEST_CASE("wake-ahead: it learns to cover the slow wake-ups of an idle machine, and ticks stop being late") {
	// One wake-up in 500 is 300 us late: beyond the starting spin, within the cap.
	ScriptedLoop loop;
	loop.run(static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(15'000, 500, 300'000));
	const int64_t late_while_starting = loop.late_ticks;
	CHECK(late_while_starting >= static_cast<int64_t>(WAKE_AHEAD_WINDOW) / 500 - 1);
	const int64_t ahead = loop.wake_ahead.ahead_ns();
	CHECK(ahead >= 300'000);
	CHECK(ahead <= 302'000); // The bin's upper edge, no more.
	loop.late_ticks = 0;
	loop.run(4 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(15'000, 500, 300'000));
	CHECK(loop.late_ticks == 0);
}

TEST_CASE("wake-ahead: it covers the chosen quantile, not the rarest wake-up") {
	// One in 2 000 is 400 us late: fewer than the 0.1 % the quantile leaves out.
	ScriptedLoop loop;
	loop.run(4 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(15'000, 2'000, 400'000));
	CHECK(loop.wake_ahead.ahead_ns() < 30'000);
}

TEST_CASE("wake-ahead: bounded by its cap, half a period and RLIMIT_RTTIME") {
	CHECK(wake_ahead_cap_ns(1000.0, 0) == WAKE_AHEAD_MAX_NS);
	CHECK(wake_ahead_cap_ns(4000.0, 0) == 125'000); // Half a 250 us period.
	CHECK(wake_ahead_cap_ns(1000.0, 200'000) == WAKE_AHEAD_MAX_NS); // RealtimeKit's 200 ms.
	CHECK(wake_ahead_cap_ns(1000.0, 100) == 50'000); // A tiny budget: half of it.

	// Every wake-up just under the cap late: the cap.
	ScriptedLoop loop;
	loop.run(2 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(WAKE_AHEAD_MAX_NS - 5'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.ahead_ns() == WAKE_AHEAD_MAX_NS);
	ScriptedLoop fast(wake_ahead_cap_ns(4000.0, 0));
	CHECK(fast.wake_ahead.ahead_ns() == std::min<int64_t>(UNHELD_SPIN_NS, 125'000));
	fast.run(2 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(WAKE_AHEAD_MAX_NS - 5'000, 1'000'000, 0));
	CHECK(fast.wake_ahead.ahead_ns() == 125'000);
}

TEST_CASE("wake-ahead: stalls no spin covers are left out, and cost no spin") {
	// A loaded machine: one wake-up in 100 stalls 2 ms, the rest come within 20 us. Covering
	// the stalls' share would spin the cap every tick and still leave them late.
	ScriptedLoop loop;
	loop.run(3 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(15'000, 100, 2'000'000));
	CHECK(loop.wake_ahead.ahead_ns() < 30'000);
	// Every wake-up stalls: nothing to cover, the least spin.
	ScriptedLoop stalled;
	stalled.run(2 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(2'000'000, 1'000'000, 0));
	CHECK(stalled.wake_ahead.ahead_ns() == WAKE_AHEAD_MIN_NS);
}

TEST_CASE("wake-ahead: it forgets a noisy spell within a window") {
	ScriptedLoop loop;
	loop.run(2 * static_cast<int64_t>(WAKE_AHEAD_WINDOW), mostly(200'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.ahead_ns() >= 200'000);
	loop.run(static_cast<int64_t>(WAKE_AHEAD_WINDOW) + static_cast<int64_t>(WakeAhead::UPDATE_EVERY),
			mostly(2'000, 1'000'000, 0));
	CHECK(loop.wake_ahead.ahead_ns() == WAKE_AHEAD_MIN_NS);
	// And the spin it costs follows: about the wake-ahead less the usual lateness, per tick.
	const int64_t spun_before = loop.spun_ns;
	loop.run(1000, mostly(2'000, 1'000'000, 0));
	CHECK(loop.spun_ns - spun_before <= 1000 * WAKE_AHEAD_MIN_NS);
}

TEST_CASE("wake-ahead: a sleep asked for a time already past is an overrun, not a wake-up") {
	WakeAhead wake_ahead;
	wake_ahead.reset(UNHELD_SPIN_NS, WAKE_AHEAD_MAX_NS);
	for (size_t k = 0; k < 2 * WAKE_AHEAD_WINDOW; ++k) {
		const auto t = static_cast<int64_t>(k) * PERIOD_NS;
		// Each began 10 us after its target and returned 900 us after it.
		CHECK_FALSE(wake_ahead.observe(t + 10'000, t, t + 900'000));
	}
	CHECK_FALSE(wake_ahead.learned());
	CHECK(wake_ahead.ahead_ns() == UNHELD_SPIN_NS);
}
