#pragma once

// Clock and scheduling primitives of the servo thread, one implementation per platform
// (realtime_linux.cpp, realtime_windows.cpp; the Windows counterparts of each technique are
// described there and reported through the same RealtimeGrants fields). CLOCK_MONOTONIC everywhere: it never
// jumps with NTP or the user changing the time, and clock_nanosleep with TIMER_ABSTIME on it
// sleeps to an absolute deadline, so a late wake-up does not push every later tick back
// (the drift a relative sleep_for accumulates).
//
// What a real-time thread can ask of Linux, each technique measured against cyclictest in the
// same run (haptics_rt_bench; docs/servo-timing.md) and each falling back quietly where it
// is not permitted: a SCHED_FIFO priority, locked memory (mlockall), the CPU's wake-up latency
// held at 0 (/dev/cpu_dma_latency, which keeps idle cores out of deep sleep states), pinning
// to one CPU, a prefaulted stack, and, when SCHED_FIFO is refused, the smallest timer slack.
// None of these functions logs; each says what it got.

#include "core/base/realtime_kit.h"

#include <cstdint>

namespace haptics {

// SchedulerKind (realtime.schema.toml): MANUAL is step(dt), no thread; NORMAL is SCHED_OTHER
// (SCHED_FIFO refused or not asked for); REALTIME_FIFO; REALTIME_RR from RealtimeKit (a normal
// user's real time); on Windows MMCSS_PRO_AUDIO or MMCSS_GAMES, the multimedia class
// scheduler's tasks, which raise the thread into the real-time range a normal user may have.

// Its label for people ("SCHED_FIFO").
const char *scheduler_kind_name(SchedulerKind p_kind);
// Whether p_kind is one of the real-time classes (SCHED_FIFO, SCHED_RR, an MMCSS task).
bool is_realtime_kind(SchedulerKind p_kind);

// Names the calling thread (15 characters at most: what Linux keeps) for the OS's tools.
void set_current_thread_name(const char *p_name);

// Nanoseconds of CLOCK_MONOTONIC.
int64_t monotonic_now_ns();

// Sleeps until CLOCK_MONOTONIC reaches p_deadline_ns (returns at once if it has passed);
// restarts after signals.
void sleep_until_ns(int64_t p_deadline_ns);

// Sleeps until p_spin_ns before p_deadline_ns, then busy-waits (a pause instruction per
// spin) until the deadline: the wake-up's lateness is absorbed by the spin, at the cost of up
// to p_spin_ns of CPU per call. p_spin_ns <= 0 is sleep_until_ns. Returns when the sleep
// ended (before the spin): how late the wake-up itself was, for the wake-ahead that learns it.
int64_t sleep_then_spin_until_ns(int64_t p_deadline_ns, int64_t p_spin_ns);

// Relative sleep, for the naive baseline loop of the benchmark only.
void sleep_for_ns(int64_t p_duration_ns);

// CPU time the calling thread has used, in nanoseconds (a system call: not every tick).
int64_t thread_cpu_time_ns();

struct RealtimeResult {
	SchedulerKind kind = SchedulerKind::NORMAL;
	int32_t priority = 0;
};

// Asks for SCHED_FIFO at p_priority (clamped to the system's range) for the calling thread.
// Without the privilege (no CAP_SYS_NICE, no rtprio limit) it quietly stays SCHED_OTHER and
// says so; it never logs. p_priority <= 0 does not ask at all.
RealtimeResult try_make_current_thread_realtime(int32_t p_priority);

// Pinning choices besides a CPU index.
constexpr int32_t PIN_NONE = -1; // Let the scheduler place the thread.
constexpr int32_t PIN_AUTO = -2; // The highest-numbered CPU the thread may run on (CPU 0
								 // usually serves more interrupts and housekeeping).

// Pins the calling thread to p_cpu (or per PIN_AUTO); returns the CPU, or -1 when not pinned
// (PIN_NONE, a CPU outside the thread's allowed set, or refused).
int32_t try_pin_current_thread(int32_t p_cpu);

// Touches p_kb KiB of the calling thread's stack below the current frame, bounded by the
// stack's size less a margin, so that the tick never takes a page fault on its stack; returns
// the KiB touched.
int32_t prefault_current_stack(int32_t p_kb);

// Sets the calling thread's timer slack to 1 ns (SCHED_OTHER threads otherwise wake up to
// 50 us late by default; SCHED_FIFO threads have none). Returns whether it was set.
bool minimise_current_timer_slack();

// Process-wide holds, counted: any number of servos may hold them; the memory stays locked
// and the latency held until the last one lets go.
//
// Locks the process's memory (mlockall: current and future pages, each as it is faulted in,
// MCL_ONFAULT, so that a large process is not populated at once). Only asked for when the
// lock cannot fail later: with CAP_IPC_LOCK or an unlimited RLIMIT_MEMLOCK (with a finite
// limit, MCL_FUTURE would make the game's own allocations fail once it is reached).
bool acquire_memory_lock();
void release_memory_lock();
// Holds /dev/cpu_dma_latency at 0 us (the kernel's PM QoS request: idle CPUs poll instead of
// entering sleep states they wake from late). Needs write access to the file: root, or the
// logged-in user where the project's udev rule grants it (tools/udev/70-haptics.rules).
bool acquire_cpu_latency_hold();
void release_cpu_latency_hold();

// What the servo thread asks for. The defaults are the servo's (ServoOptions), each chosen by
// measuring it on its own against cyclictest in the same run, idle, under CPU load and under
// rendering load (haptics_rt_bench --techniques; the figures: docs/servo-timing.md, "The
// techniques and their defaults"):
//   - SCHED_FIFO 80 rather than 50: better under rendering load (the game's own servo and
//     audio compete), the same elsewhere: on.
//   - mlockall: p99.9 worse in every condition, and it locks the whole game: off.
//   - cpu_dma_latency 0: within the noise while the host was quiet, but the one technique
//     that held the servo near cyclictest once the host got busy (a headless game running
//     beside it): an idle vCPU that halts waits for the host to run it again; one that polls
//     does not. On, at the cost of idle cores polling while the servo runs (cyclictest holds
//     it too).
//   - pinning: worse under CPU load (a pinned thread cannot leave a busy core): off.
//   - stack prefault: no difference beyond the noise: off (available).
//   - timer slack 1 ns under SCHED_OTHER: about half the median wake latency: on (it only
//     applies where SCHED_FIFO is refused).
// As an ordinary user (haptics_rt_bench --user nobody --user-techniques, the user's rows
// beside root's in the same rounds): SCHED_FIFO, mlockall and cpu_dma_latency need root (or
// CAP_SYS_NICE / an rtprio limit, CAP_IPC_LOCK / an unlimited memlock limit, write access to
// the file, which the project's udev rule gives the logged-in user); RealtimeKit's SCHED_RR 20
// stands in for the first, and root's servo configured like that grant (FIFO 20, no latency
// hold) was within the noise of root's as shipped.
// Pinning, the timer slack, the spin and RLIMIT_RTTIME need nothing; pinning gained nothing
// for the user either, and the spin is worth it only to a real-time thread (ServoOptions).
struct RealtimeRequest {
	int32_t priority = 80; // SCHED_FIFO priority; 0 = do not ask.
	bool lock_memory = false;
	bool hold_cpu_latency = true;
	int32_t cpu = PIN_NONE; // A CPU index, PIN_NONE or PIN_AUTO.
	int32_t prefault_stack_kb = 0; // 0 = none.
	bool minimise_timer_slack = true; // Only when real time is not granted.
	// When SCHED_FIFO is refused (a normal user), ask RealtimeKit for SCHED_RR at priority
	// (or the most it allows), else for a raised nice level.
	bool ask_realtime_kit = true;
};

// What it got.
struct RealtimeGrants {
	SchedulerKind kind = SchedulerKind::NORMAL;
	int32_t priority = 0;
	bool memory_locked = false;
	bool cpu_latency_held = false;
	int32_t cpu = -1; // Pinned CPU, -1 when not pinned.
	int32_t stack_prefaulted_kb = 0;
	bool timer_slack_minimised = false; // Only tried when real time was not granted.
	RtkitGrant realtime_kit; // What RealtimeKit was asked and gave (NOT_ASKED under SCHED_FIFO).
};

// On the thread to be made real-time: asks for everything p_request names, in that order
// (the process-wide holds first), and returns what was granted.
RealtimeGrants apply_realtime_request(const RealtimeRequest &p_request);
// Releases the process-wide holds p_grants took (the thread's own settings end with it).
void release_realtime_grants(const RealtimeGrants &p_grants);

} // namespace haptics
