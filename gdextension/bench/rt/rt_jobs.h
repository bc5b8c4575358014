#pragma once

// What haptics_rt_bench measures in each condition, in the order of the first round (the
// order rotates from round to round): the servo as shipped, cyclictest, then each optional
// measurement, each a Job.
//
// With --user the servo is measured again as that ordinary user (rt_users.h): without
// RealtimeKit; with it (the spin learned, wake_ahead.h); with it and the fixed spin the learned
// one replaced (UNHELD_SPIN_NS); with it and /dev/cpu_dma_latency given as the project's udev
// rule gives it; and as root configured like the user's grant (SCHED_FIFO at RealtimeKit's
// maximum priority, no /dev/cpu_dma_latency), which separates what the priority and the
// latency hold are each worth. With --user-techniques, also what else an
// ordinary user can set for themselves: the spin before each deadline, pinning, the timer
// slack; and root at FIFO 80 without the latency hold and at RealtimeKit's priority with it.

#include "core/servo/servo_loop.h"

#include <string>
#include <vector>

namespace haptics::bench {

// RealtimeKit's default MaxRealtimePriority (rtkit 0.13; docs/realtime.md): the most a user is granted,
// and the priority of the root rows that stand in for that grant. The user rows print the
// priority they were granted, so a daemon configured otherwise shows.
inline constexpr int32_t RTKIT_DEFAULT_MAX_PRIORITY = 20;

enum class JobKind {
	SERVO, // In this process (root when the benchmark is).
	CYCLICTEST,
	USER_SERVO, // As the --user, in a child (rt_users.h).
};

struct Job {
	std::string label;
	JobKind kind = JobKind::SERVO;
	ServoOptions options; // USER_SERVO: only what a user_child_arguments() carries.
	bool rtkit = false; // USER_SERVO: with the RealtimeKit bus (else none).
	bool latency_access = false; // USER_SERVO: the user may open /dev/cpu_dma_latency meanwhile.
};

struct JobPlan {
	bool techniques = false; // Root's techniques, each on its own against the old servo.
	std::string user; // Empty: no user rows.
	bool rtkit = false; // A RealtimeKit bus was given for the user.
	bool user_techniques = false;
};

std::vector<Job> plan_jobs(const JobPlan &p_plan);

// The options a user child takes on its command line (spin, pinning, timer slack), to and from
// arguments; the rest is the shipped servo's.
std::vector<std::string> user_child_arguments(const ServoOptions &p_options);
// Consumes one option of user_child_arguments() at p_argv[r_index] (advancing past its value);
// false when p_argv[r_index] is not one.
bool parse_user_child_argument(int p_argc, char **p_argv, int &r_index, ServoOptions &r_options);

} // namespace haptics::bench
