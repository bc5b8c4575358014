// haptics_bench: the servo loop under load, against a naive baseline, in one run; then the
// tick-cost micro-benchmarks and the finite proxy's cost against the number of walls.
//
//   haptics_bench [--duration S | --seconds S] [--json PATH] [--rate HZ] [--proxy-only | --no-proxy]
//   (positional forms also work: haptics_bench 10 .bench/servo.json)
//
// For each loop (absolute deadlines, then sleep_for(period) with no deadline tracking) the
// servo runs for S seconds (default 10) on the simulated device while a 50 Hz producer
// thread, standing in for the game, submits frames, pushes an impact every 100 ms, moves the
// hand and drains telemetry. Prints a side-by-side table with ratios and the targets, then
// the tick-cost micro-benchmarks and the proxy benchmark (proxy_bench.cpp: 100 / 1 000 /
// 10 000 walls, uniform grid vs brute force), and writes everything as JSON (default
// .bench/servo.json; --proxy-only skips the loops and writes only the proxy section).
// Reports; never asserts: timing depends on the machine.

#include "bench_report.h"
#include "servo_workload.h"

#include "system/haptics_system.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

using namespace haptics;
using namespace haptics::bench;

namespace {

struct Options {
	double duration_s = 10.0;
	double rate_hz = 1000.0;
	std::string json_path = ".bench/servo.json";
	bool loops = true;
	bool proxy = true;
};

bool parse(int p_argc, char **p_argv, Options &r_options) {
	bool have_positional_duration = false;
	for (int a = 1; a < p_argc; ++a) {
		const std::string arg = p_argv[a];
		const bool has_value = a + 1 < p_argc;
		if ((arg == "--duration" || arg == "--seconds") && has_value) {
			r_options.duration_s = std::atof(p_argv[++a]);
		} else if (arg == "--rate" && has_value) {
			r_options.rate_hz = std::atof(p_argv[++a]);
		} else if (arg == "--json" && has_value) {
			r_options.json_path = p_argv[++a];
		} else if (arg == "--proxy-only") {
			r_options.loops = false;
		} else if (arg == "--no-proxy") {
			r_options.proxy = false;
		} else if (arg == "--help" || arg == "-h" || arg.rfind("--", 0) == 0) {
			return false; // Help, an unknown flag, or a flag missing its value.
		} else if (!have_positional_duration && std::strtod(arg.c_str(), nullptr) > 0.0) {
			r_options.duration_s = std::atof(arg.c_str());
			have_positional_duration = true;
		} else {
			r_options.json_path = arg;
		}
	}
	return r_options.duration_s > 0.0 && std::isfinite(r_options.duration_s);
}

LoopResult run_loop(const char *p_name, LoopScheduling p_scheduling, const Options &p_options) {
	ServoOptions servo;
	servo.rate_hz = p_options.rate_hz;
	servo.scheduling = p_scheduling;
	return run_servo_workload(p_name, servo, p_options.duration_s);
}

} // namespace

int main(int p_argc, char **p_argv) {
	Options options;
	if (!parse(p_argc, p_argv, options)) {
		std::fprintf(stderr, "usage: %s [--duration S | --seconds S] [--json PATH] [--rate HZ] [--proxy-only | --no-proxy]\n",
				p_argv[0]);
		return 1;
	}
	if (!validate_rate(options.rate_hz)) {
		std::fprintf(stderr, "%s\n", validate_rate(options.rate_hz).message());
		return 1;
	}
	std::printf("haptics_bench: %.1f s per loop at %.0f Hz, %u hardware threads\n", options.duration_s, options.rate_hz,
			std::thread::hardware_concurrency());
	std::fflush(stdout);
	std::vector<ProxyBenchResult> proxy;
	if (!options.loops) {
		proxy = run_proxy_benchmarks();
		print_proxy_report(proxy);
		if (!write_json(options.json_path, nullptr, nullptr, {}, proxy)) {
			return 1;
		}
		std::printf("\nwrote %s\n", options.json_path.c_str());
		return 0;
	}
	const LoopResult deadline = run_loop("deadline", LoopScheduling::DEADLINE, options);
	const LoopResult naive = run_loop("naive", LoopScheduling::NAIVE_SLEEP, options);
	const std::vector<MicroResult> micro = run_micro_benchmarks();
	print_report(deadline, naive, micro);
	if (options.proxy) {
		proxy = run_proxy_benchmarks();
		print_proxy_report(proxy);
	}
	if (!write_json(options.json_path, &deadline, &naive, micro, proxy)) {
		return 1;
	}
	std::printf("\nwrote %s\n", options.json_path.c_str());
	return 0;
}
