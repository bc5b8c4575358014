#pragma once

// The servo benchmarks' workload, shared by haptics_bench and haptics_rt_bench: the servo on
// the simulated device while a 50 Hz producer thread, standing in for the game, submits
// frames, pushes an impact every 100 ms, moves the hand and drains telemetry.

#include "bench_report.h"

#include "core/servo/servo_loop.h"

namespace haptics::bench {

// Runs the servo with p_options for p_duration_s seconds under that workload; exits the
// program (status 2) if the simulated device or the servo cannot start.
LoopResult run_servo_workload(const char *p_name, const ServoOptions &p_options, double p_duration_s);

} // namespace haptics::bench
