#pragma once

// Clock and scheduling primitives of the servo thread. CLOCK_MONOTONIC everywhere: it never
// jumps with NTP or the user changing the time, and clock_nanosleep with TIMER_ABSTIME on it
// sleeps to an absolute deadline, so a late wake-up does not push every later tick back
// (the drift a relative sleep_for accumulates).

#include "core/servo_stats.h"

#include <cstdint>

namespace haptics {

// Nanoseconds of CLOCK_MONOTONIC.
int64_t monotonic_now_ns();

// Sleeps until CLOCK_MONOTONIC reaches p_deadline_ns (returns at once if it has passed);
// restarts after signals.
void sleep_until_ns(int64_t p_deadline_ns);

// Relative sleep, for the naive baseline loop of the benchmark only.
void sleep_for_ns(int64_t p_duration_ns);

struct RealtimeResult {
	SchedulerKind kind = SchedulerKind::NORMAL;
	int32_t priority = 0;
};

// Asks for SCHED_FIFO at p_priority (clamped to the system's range) for the calling thread.
// Without the privilege (no CAP_SYS_NICE, no rtprio limit) it quietly stays SCHED_OTHER and
// says so; it never logs. p_priority <= 0 does not ask at all.
RealtimeResult try_make_current_thread_realtime(int32_t p_priority);

} // namespace haptics
