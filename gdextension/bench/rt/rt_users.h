#pragma once

// The servo as an ordinary user gets it, measured inside the root benchmark's rounds: the same
// binary runs again as that user (setpriv: the user's uid and gid, no groups, no capabilities)
// with "--servo-child SECONDS" and a system bus of the caller's choosing (a private one with
// RealtimeKit on it, or none), measures the servo once and hands its statistics back on
// stdout. The loads (CPU, rendering) are the root benchmark's own, running meanwhile.

#include "core/servo/servo_loop.h"
#include "core/servo/servo_stats.h"
#include "rt_results.h"

#include <string>

namespace haptics::bench {

struct ServoChildReport {
	ServoStats stats;
	double steal_percent = 0.0;
	uint32_t latency_bins[ServoStatsRecorder::LATENCY_BINS] = {}; // For pooling (rt_pool.h).
};

// In the child: p_report to stdout, for the parent. False if it could not be written.
bool write_child_report(const ServoChildReport &p_report);

// Runs this program as p_user, on the system bus p_bus ("" = none: RealtimeKit unavailable),
// measuring the servo with what p_options sets of user_child_arguments() (rt_jobs.h) for
// p_seconds. With p_latency_access the user may open /dev/cpu_dma_latency meanwhile, as the
// project's udev rule lets the logged-in user (an ACL entry, taken back after; the calling
// script restores the file's ACL if this program dies first). False with the reason when it
// could not.
bool run_servo_child(const std::string &p_user, const std::string &p_bus, const ServoOptions &p_options,
		bool p_latency_access, double p_seconds, ServoChildReport &r_report, std::string &r_error);

// The rows of p_result measured as an ordinary user (labels starting "as ") and root's rows
// configured like the user's grant (starting "root, "), next to root's servo as shipped in
// the same condition: wake latency p99 and p99.9 (pooled, with p99.9's interval) and their
// ratios (goal for the user with RealtimeKit: within GOAL_RATIO), the spin, and the CPU each
// used.
void print_user_comparison(const ConditionResult &p_result);

} // namespace haptics::bench
