#pragma once

// A client of RealtimeKit (rtkit-daemon, D-Bus system service org.freedesktop.RealtimeKit1):
// the way a normal user's process gets a real-time thread on a stock Linux desktop, where
// SCHED_FIFO is refused (no rtprio limit, no CAP_SYS_NICE). PipeWire and PulseAudio ask it
// the same way. It grants SCHED_RR (with SCHED_RESET_ON_FORK) up to MaxRealtimePriority to a
// thread whose process has set RLIMIT_RTTIME (at most RTTimeUSecMax); failing that, a nice
// level down to MinNiceLevel. Its polkit actions allow active and inactive login sessions by
// default, not a process without one (docs/realtime.md, "RealtimeKit").
//
// libdbus is loaded when first needed (dlopen "libdbus-1.so.3", every desktop has it), so
// the library has no link-time dependency on it and an export runs where it is absent. The
// bus is DBUS_SYSTEM_BUS_ADDRESS when set (the tests' private bus), else the system's.
//
// Blocking (one round trip each, bounded by a timeout): call it from the servo thread before
// its loop starts, never from the tick.

#include <cstdint>

namespace haptics {

enum class RtkitOutcome : int32_t {
	NOT_ASKED = 0, // SCHED_FIFO was granted, or asking RealtimeKit is turned off.
	REALTIME = 1, // SCHED_RR granted.
	HIGH_PRIORITY = 2, // Real time refused; a raised nice level granted.
	REFUSED = 3, // Both refused (e.g. no login session: polkit says no).
	UNAVAILABLE = 4, // No libdbus, no system bus, or no RealtimeKit on it.
};

// "not asked", "realtime", "high priority", "refused", "unavailable".
const char *rtkit_outcome_name(RtkitOutcome p_outcome);

struct RtkitGrant {
	RtkitOutcome outcome = RtkitOutcome::NOT_ASKED;
	int32_t priority = 0; // SCHED_RR priority when REALTIME.
	int32_t nice = 0; // Nice level when HIGH_PRIORITY.
	int32_t max_priority = 0; // What the daemon allows (MaxRealtimePriority); 0 when unknown.
	int64_t rttime_usec = 0; // The RLIMIT_RTTIME set for it; 0 when none.
	char reason[160] = {}; // Why not, when REFUSED or UNAVAILABLE; what was granted otherwise.
};

// Asks RealtimeKit to make the calling thread real-time at p_priority (lowered to what it
// allows), setting SCHED_RESET_ON_FORK on the thread and the process's RLIMIT_RTTIME to the
// daemon's maximum first, as it requires; if that is refused, asks for the lowest nice level
// it allows. Never logs.
RtkitGrant request_realtime_from_rtkit(int32_t p_priority);

} // namespace haptics
