// haptics_rt_bench: the servo's timing next to the machine's limit, in one run. For each
// condition (idle; CPU load: a busy thread per core; rendering load: the game windowed under
// Xvfb on the software renderer) the servo (shipped defaults, simulated device, the benchmark
// workload of servo_workload.h) and cyclictest (rt-tests, at the servo's period and
// priority) take turns: R rounds, each running every measurement for S seconds, the order
// rotating from round to round, so that a noisy minute of a shared machine does not land on
// one side only. The wake latency's figures pool every tick of every round into one histogram,
// with a 95 % interval for p99.9 from the rounds (rt_pool.h); the jitter's are medians over the
// rounds (the max: the largest of all). The two are printed side by side with their ratio:
//   - wake latency: how long after its deadline each tick woke (cyclictest's own measure)
//   - period jitter: |period - nominal period| (cyclictest's from consecutive latencies)
// Both are binned identically (1 us bins, servo_stats.h). With --techniques each round also
// runs each real-time technique (realtime.h) on its own against the old servo (SCHED_FIFO 50
// and nothing else), and spins of several lengths with their CPU cost.
//
//   haptics_rt_bench [--seconds S] [--rounds R] [--json PATH] [--project DIR]
//                    [--conditions idle,cpu,render] [--techniques]
//                    [--user USER [--rtkit-bus ADDRESS] [--user-techniques]]
//
// With --user (as root) each round also measures the servo as that ordinary user gets it
// (rt_users.h): without RealtimeKit, and with the one on the system bus ADDRESS (a private
// one, tools/rt/bench-users.sh), under the same loads, and root configured like the user's
// grant; --user-techniques adds what else the user can set (rt_jobs.h). cyclictest refuses to
// run for a user without real-time rights, so the ratios of those rows are to root's
// cyclictest.
//
// Also prints the end-to-end latency in ticks (latency.h). Reports; never asserts. A
// condition that cannot be set up here (no Xvfb, no engine, no cyclictest) is reported as not
// measured, with the reason. Every process it starts (Xvfb, the game, cyclictest) is stopped
// by its PID.

#include "../servo_workload.h"
#include "latency.h"
#include "rt_jobs.h"
#include "rt_processes.h"
#include "rt_report.h"
#include "rt_results.h"
#include "rt_users.h"

#include "core/base/realtime.h"
#include "core/servo/servo_stats.h"
#include "system/haptics_system.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace haptics;
using namespace haptics::bench;

namespace {

struct Options {
	double seconds = 10.0; // Per measurement per round.
	int rounds = 5;
	std::string json_path = ".bench/rt.json";
	std::string project = ".";
	std::vector<std::string> conditions = { "idle", "cpu", "render" };
	bool techniques = false;
	std::string user; // Also measure the servo as this user.
	std::string rtkit_bus; // And as that user with the RealtimeKit on this bus.
	bool user_techniques = false; // And what else that user can set (rt_jobs.h).
	ServoOptions child_options; // --servo-child: what the parent asked for (rt_jobs.h).
	double child_seconds = 0.0; // > 0: this is a child of --user's: measure once, report, exit.
};

ToolResult servo_result(const ServoStats &p_stats, double p_steal_percent, const uint32_t *p_bins, size_t p_count) {
	ToolResult result;
	result.steal_percent = p_steal_percent;
	result.measured = true;
	result.stats = p_stats;
	result.latency = from_stats_latency(p_stats);
	result.latency_bins = { std::vector<uint32_t>(p_bins, p_bins + p_count), p_stats.latency_max_s };
	result.jitter = from_stats_jitter(p_stats);
	result.rate_error_percent = rate_error_percent(p_stats);
	result.cpu_fraction = p_stats.thread_cpu_fraction;
	return result;
}

ToolResult run_servo(const ServoOptions &p_options, double p_seconds) {
	const CpuTimes before = read_cpu_times();
	const LoopResult loop = run_servo_workload("servo", p_options, p_seconds);
	return servo_result(loop.stats, steal_percent(before, read_cpu_times()), loop.latency_bins.data(),
			loop.latency_bins.size());
}

ToolResult run_servo_as(const std::string &p_user, const std::string &p_bus, const ServoOptions &p_options,
		bool p_latency_access, double p_seconds) {
	const auto report = std::make_unique<ServoChildReport>();
	std::string error;
	if (!run_servo_child(p_user, p_bus, p_options, p_latency_access, p_seconds, *report, error)) {
		ToolResult result;
		result.why_not = error;
		return result;
	}
	return servo_result(report->stats, report->steal_percent, report->latency_bins, std::size(report->latency_bins));
}

// cyclictest at the servo's period and priority, its default tuning (memory locked with -m,
// /dev/cpu_dma_latency 0 while it runs); every loop's latency in ns (-v -N).
ToolResult run_cyclictest(int32_t p_priority, double p_rate_hz, double p_seconds) {
	ToolResult result;
	const int64_t interval_us = std::llround(1e6 / p_rate_hz);
	const int64_t loops = std::llround(p_seconds * p_rate_hz);
	std::vector<std::string> argv = { "cyclictest", "-m", "-i", std::to_string(interval_us), "-l", std::to_string(loops),
		"-q", "-v", "-N" };
	if (p_priority > 0) {
		argv.insert(argv.begin() + 1, { "-p", std::to_string(p_priority) });
	}
	std::string output;
	std::string error;
	const CpuTimes before = read_cpu_times();
	const bool ran = run_and_capture(argv, p_seconds * 3.0 + 30.0, output, error);
	result.steal_percent = steal_percent(before, read_cpu_times());
	if (!ran) {
		result.why_not = "cyclictest: " + error;
		return result;
	}
	Histogram<ServoStatsRecorder::LATENCY_BINS> latency(1e-6);
	Histogram<20000> jitter(1e-6);
	latency.reset();
	jitter.reset();
	std::istringstream lines(output);
	std::string line;
	long long previous = -1;
	while (std::getline(lines, line)) {
		long long thread = 0, cycle = 0, value_ns = 0;
		if (std::sscanf(line.c_str(), " %lld: %lld: %lld", &thread, &cycle, &value_ns) != 3) {
			continue;
		}
		latency.record(static_cast<double>(value_ns) * 1e-9);
		if (previous >= 0) {
			jitter.record(static_cast<double>(std::llabs(value_ns - previous)) * 1e-9);
		}
		previous = value_ns;
	}
	if (latency.count() < static_cast<uint64_t>(loops) * 9 / 10) {
		result.why_not = "cyclictest printed " + std::to_string(latency.count()) + " of " + std::to_string(loops) + " loops";
		return result;
	}
	result.measured = true;
	result.latency = { true, latency.percentile(0.5), latency.percentile(0.99), latency.percentile(0.999), latency.max(),
		latency.count() };
	result.latency_bins = { std::vector<uint32_t>(ServoStatsRecorder::LATENCY_BINS), latency.max() };
	latency.copy_bins(result.latency_bins.bins.data(), result.latency_bins.bins.size());
	result.jitter = { true, jitter.percentile(0.5), jitter.percentile(0.99), jitter.percentile(0.999), jitter.max(),
		jitter.count() };
	return result;
}

// One busy thread per hardware thread, SCHED_OTHER, until destroyed.
class CpuLoad {
public:
	CpuLoad() {
		const unsigned count = std::max(1u, std::thread::hardware_concurrency());
		for (unsigned t = 0; t < count; ++t) {
			threads_.emplace_back([this] {
				volatile uint64_t sink = 0;
				while (!stop_.load(std::memory_order_relaxed)) {
					for (int i = 0; i < 10000; ++i) {
						sink = sink * 6364136223846793005ULL + 1442695040888963407ULL;
					}
				}
			});
		}
	}
	~CpuLoad() {
		stop_.store(true);
		for (std::thread &thread : threads_) {
			thread.join();
		}
	}
	size_t threads() const { return threads_.size(); }

private:
	std::atomic<bool> stop_{ false };
	std::vector<std::thread> threads_;
};

bool parse(int p_argc, char **p_argv, Options &r_options) {
	for (int a = 1; a < p_argc; ++a) {
		const std::string arg = p_argv[a];
		const bool has_value = a + 1 < p_argc;
		if (arg == "--seconds" && has_value) {
			r_options.seconds = std::atof(p_argv[++a]);
		} else if (arg == "--rounds" && has_value) {
			r_options.rounds = std::atoi(p_argv[++a]);
		} else if (arg == "--json" && has_value) {
			r_options.json_path = p_argv[++a];
		} else if (arg == "--project" && has_value) {
			r_options.project = p_argv[++a];
		} else if (arg == "--conditions" && has_value) {
			r_options.conditions.clear();
			std::istringstream list(p_argv[++a]);
			std::string name;
			while (std::getline(list, name, ',')) {
				if (name != "idle" && name != "cpu" && name != "render") {
					return false;
				}
				r_options.conditions.push_back(name);
			}
		} else if (arg == "--techniques") {
			r_options.techniques = true;
		} else if (arg == "--user" && has_value) {
			r_options.user = p_argv[++a];
		} else if (arg == "--rtkit-bus" && has_value) {
			r_options.rtkit_bus = p_argv[++a];
		} else if (arg == "--user-techniques") {
			r_options.user_techniques = true;
		} else if (arg == "--servo-child" && has_value) {
			r_options.child_seconds = std::atof(p_argv[++a]);
		} else if (!parse_user_child_argument(p_argc, p_argv, a, r_options.child_options)) {
			return false;
		}
	}
	return r_options.seconds > 0.0 && r_options.rounds > 0;
}

} // namespace

int main(int p_argc, char **p_argv) {
	Options options;
	if (!parse(p_argc, p_argv, options)) {
		std::fprintf(stderr,
				"usage: %s [--seconds S] [--rounds R] [--json PATH] [--project DIR] [--conditions idle,cpu,render] "
				"[--techniques] [--user USER [--rtkit-bus ADDRESS] [--user-techniques]]\n",
				p_argv[0]);
		return 1;
	}
	const ServoOptions shipped;
	if (options.child_seconds > 0.0) {
		const ToolResult once = run_servo(options.child_options, options.child_seconds);
		const auto report = std::make_unique<ServoChildReport>();
		report->stats = once.stats;
		report->steal_percent = once.steal_percent;
		std::copy_n(once.latency_bins.bins.begin(), std::min(once.latency_bins.bins.size(), std::size(report->latency_bins)),
				report->latency_bins);
		return write_child_report(*report) ? 0 : 1;
	}
	std::printf("haptics_rt_bench: the servo (shipped defaults, simulated device, 50 Hz producer) next to cyclictest "
				"at %.0f Hz: %d rounds of %.1f s each per condition, order rotating; %u hardware threads\n",
			shipped.rate_hz, options.rounds, options.seconds, std::thread::hardware_concurrency());
	std::printf("wake latency = wake-up time - deadline (cyclictest's measure); period jitter = |period - nominal|; "
				"1 us bins; wake latency pooled over every tick of every round, p99.9 [95 %% interval from the rounds]; "
				"jitter p50/p99/p99.9 = median over the rounds; max = largest; ratio = servo / cyclictest, goal <= %.2f\n",
			GOAL_RATIO);
	std::fflush(stdout);

	const std::vector<LatencyResult> latencies = measure_latencies();
	print_latencies(latencies, shipped.rate_hz);
	std::fflush(stdout);

	std::vector<ConditionResult> results;
	for (const std::string &name : options.conditions) {
		ConditionResult result;
		result.name = name;
		std::unique_ptr<CpuLoad> cpu_load;
		std::unique_ptr<RenderLoad> render_load;
		if (name == "idle") {
			result.detail = "nothing else of ours running";
		} else if (name == "cpu") {
			cpu_load = std::make_unique<CpuLoad>();
			result.detail = std::to_string(cpu_load->threads()) + " busy threads (one per hardware thread, SCHED_OTHER)";
		} else {
			render_load = std::make_unique<RenderLoad>(options.project);
			std::string why_not;
			if (!render_load->start(why_not)) {
				result.why_not = why_not;
				result.detail = "the game windowed under Xvfb, software renderer";
				print_condition(result);
				results.push_back(result);
				continue;
			}
			result.detail = render_load->describe();
		}
		const std::vector<Job> jobs = plan_jobs({ options.techniques, options.user, !options.rtkit_bus.empty(),
				options.user_techniques });
		std::printf("\n[%s] measuring: %d rounds of %zu measurements x %.1f s...\n", name.c_str(), options.rounds, jobs.size(),
				options.seconds);
		std::fflush(stdout);
		std::vector<std::vector<ToolResult>> runs(jobs.size());
		// cyclictest runs at the priority the servo gets here (none when SCHED_FIFO is refused).
		int32_t priority = 0;
		std::thread([&] { priority = try_make_current_thread_realtime(shipped.realtime.priority).priority; }).join();
		for (int round = 0; round < options.rounds; ++round) {
			for (size_t k = 0; k < jobs.size(); ++k) {
				const size_t index = (k + static_cast<size_t>(round)) % jobs.size();
				const Job &job = jobs[index];
				std::vector<ToolResult> &run = runs[index];
				switch (job.kind) {
					case JobKind::CYCLICTEST:
						run.push_back(run_cyclictest(priority, shipped.rate_hz, options.seconds));
						break;
					case JobKind::USER_SERVO:
						run.push_back(run_servo_as(options.user, job.rtkit ? options.rtkit_bus : "", job.options,
								job.latency_access, options.seconds));
						break;
					case JobKind::SERVO:
						run.push_back(run_servo(job.options, options.seconds));
						break;
				}
			}
		}
		result.servo = combine(runs[0]);
		result.cyclictest_priority = result.servo.stats.realtime_priority;
		result.cyclictest = combine(runs[1]);
		for (size_t job = 2; job < jobs.size(); ++job) {
			result.techniques.emplace_back(jobs[job].label, combine(runs[job]));
		}
		if (render_load) {
			result.detail = render_load->describe(); // Now with its restarts.
			render_load->stop();
		}
		result.measured = true;
		print_condition(result);
		print_techniques(result);
		print_user_comparison(result);
		std::fflush(stdout);
		results.push_back(result);
	}
	if (!write_json(options.json_path, latencies, results)) {
		return 1;
	}
	std::printf("\nwrote %s\n", options.json_path.c_str());
	return 0;
}
