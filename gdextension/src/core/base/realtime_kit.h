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

#include "core/base/realtime.gen.h"

#include <cstdint>

namespace haptics {

// RtkitOutcome and RtkitGrant (realtime.schema.toml): NOT_ASKED when SCHED_FIFO was granted
// or asking is turned off; REALTIME is SCHED_RR granted; HIGH_PRIORITY a raised nice level
// after real time was refused; REFUSED both (e.g. no login session: polkit says no);
// UNAVAILABLE no libdbus, no system bus, or no RealtimeKit on it.

// Its label for people ("high priority").
const char *rtkit_outcome_name(RtkitOutcome p_outcome);

// Asks RealtimeKit to make the calling thread real-time at p_priority (lowered to what it
// allows), setting SCHED_RESET_ON_FORK on the thread and the process's RLIMIT_RTTIME to the
// daemon's maximum first, as it requires; if that is refused, asks for the lowest nice level
// it allows. Never logs.
RtkitGrant request_realtime_from_rtkit(int32_t p_priority);

} // namespace haptics
