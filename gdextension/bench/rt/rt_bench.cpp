// haptics_rt_bench: the servo's timing next to the machine's limit, in one run. For each
// condition (idle; CPU load: a busy thread per core; rendering load: the game windowed under
// Xvfb on the software renderer) the servo (shipped defaults, simulated device, the benchmark
// workload of servo_workload.h) and cyclictest (rt-tests, at the servo's period and
// priority) take turns: R rounds, each running every measurement for S seconds, the order
// rotating from round to round, so that a noisy minute of a shared machine does not land on
// one side only. Each figure is the median over the rounds (the max: the largest of all), and
// the two are printed side by side with their ratio:
//   - wake latency: how long after its deadline each tick woke (cyclictest's own measure)
//   - period jitter: |period - nominal period| (cyclictest's from consecutive latencies)
// Both are binned identically (1 us bins, servo_stats.h). With --techniques each round also
// runs each real-time technique (realtime.h) on its own against the old servo (SCHED_FIFO 50
// and nothing else), and spins of several lengths with their CPU cost.
//
//   haptics_rt_bench [--seconds S] [--rounds R] [--json PATH] [--project DIR]
//                    [--conditions idle,cpu,render] [--techniques]
//
// Also prints the end-to-end latency in ticks (latency.h). Reports; never asserts. A
// condition that cannot be set up here (no Xvfb, no engine, no cyclictest) is reported as not
// measured, with the reason. Every process it starts (Xvfb, the game, cyclictest) is stopped
// by its PID.

#include "../servo_workload.h"
#include "latency.h"
#include "rt_processes.h"

#include "core/base/realtime.h"
#include "core/servo/servo_stats.h"
#include "engine/haptics_engine.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace haptics;
using namespace haptics::bench;

namespace {

constexpr double US = 1e6;
constexpr double GOAL_RATIO = 1.25;
constexpr double RATE_GOAL_PERCENT = 0.05;

struct Options {
	double seconds = 4.0; // Per measurement per round.
	int rounds = 5;
	std::string json_path = ".bench/rt.json";
	std::string project = ".";
	std::vector<std::string> conditions = { "idle", "cpu", "render" };
	bool techniques = false;
};

struct Distribution {
	bool measured = false;
	double p50 = 0.0, p99 = 0.0, p999 = 0.0, max = 0.0; // seconds
	uint64_t count = 0;
};

// The machine's CPU time from /proc/stat's first line, in clock ticks: all of it, and the
// part the hypervisor gave to other guests (steal).
struct CpuTimes {
	unsigned long long total = 0;
	unsigned long long steal = 0;
};

CpuTimes read_cpu_times() {
	CpuTimes times;
	std::ifstream stat("/proc/stat");
	std::string cpu;
	unsigned long long field[8] = {};
	stat >> cpu;
	for (unsigned long long &value : field) {
		stat >> value;
	}
	for (const unsigned long long value : field) {
		times.total += value;
	}
	times.steal = field[7];
	return times;
}

double steal_percent(const CpuTimes &p_before, const CpuTimes &p_after) {
	const unsigned long long total = p_after.total - p_before.total;
	return total > 0 ? 100.0 * static_cast<double>(p_after.steal - p_before.steal) / static_cast<double>(total) : 0.0;
}

struct ToolResult {
	bool measured = false;
	double steal_percent = 0.0; // CPU time the hypervisor took while it ran.
	std::string why_not; // When not measured.
	Distribution latency;
	Distribution jitter;
	double rate_error_percent = 0.0;
	double worst_rate_error_percent = 0.0; // Over the rounds.
	double cpu_fraction = 0.0;
	int rounds = 1;
	ServoStats stats; // Servo only.
};

struct ConditionResult {
	std::string name;
	bool measured = false;
	std::string why_not;
	std::string detail; // How the load was made.
	ToolResult servo;
	ToolResult cyclictest;
	int32_t cyclictest_priority = 0;
	std::vector<std::pair<std::string, ToolResult>> techniques;
};

Distribution from_stats_latency(const ServoStats &p_stats) {
	return { true, p_stats.latency_p50_s, p_stats.latency_p99_s, p_stats.latency_p999_s, p_stats.latency_max_s, p_stats.ticks };
}

Distribution from_stats_jitter(const ServoStats &p_stats) {
	return { true, p_stats.jitter_p50_s, p_stats.jitter_p99_s, p_stats.jitter_p999_s, p_stats.jitter_max_s,
		p_stats.ticks > 0 ? p_stats.ticks - 1 : 0 };
}

double rate_error_percent(const ServoStats &p_stats) {
	return p_stats.nominal_rate_hz > 0.0
			? 100.0 * std::abs(p_stats.achieved_rate_hz - p_stats.nominal_rate_hz) / p_stats.nominal_rate_hz
			: 0.0;
}

ToolResult run_servo(const ServoOptions &p_options, double p_seconds) {
	const CpuTimes before = read_cpu_times();
	const LoopResult loop = run_servo_workload("servo", p_options, p_seconds);
	ToolResult result;
	result.steal_percent = steal_percent(before, read_cpu_times());
	result.measured = true;
	result.stats = loop.stats;
	result.latency = from_stats_latency(loop.stats);
	result.jitter = from_stats_jitter(loop.stats);
	result.rate_error_percent = rate_error_percent(loop.stats);
	result.cpu_fraction = loop.stats.thread_cpu_fraction;
	return result;
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
	Histogram<20000> latency(1e-6);
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
	result.jitter = { true, jitter.percentile(0.5), jitter.percentile(0.99), jitter.percentile(0.999), jitter.max(),
		jitter.count() };
	return result;
}

double median(std::vector<double> p_values) {
	if (p_values.empty()) {
		return 0.0;
	}
	std::sort(p_values.begin(), p_values.end());
	const size_t n = p_values.size();
	return n % 2 ? p_values[n / 2] : 0.5 * (p_values[n / 2 - 1] + p_values[n / 2]);
}

Distribution combine_distributions(const std::vector<const Distribution *> &p_rounds) {
	Distribution combined;
	std::vector<double> p50, p99, p999;
	for (const Distribution *d : p_rounds) {
		p50.push_back(d->p50);
		p99.push_back(d->p99);
		p999.push_back(d->p999);
		combined.max = std::max(combined.max, d->max);
		combined.count += d->count;
	}
	combined.measured = !p_rounds.empty();
	combined.p50 = median(p50);
	combined.p99 = median(p99);
	combined.p999 = median(p999);
	return combined;
}

// The rounds of one measurement: medians of the percentiles, rate error and CPU share; the
// largest max; the last round's stats (what was granted) with the counters summed. Rounds
// that could not be measured are left out; when none could, the first one's reason is kept.
ToolResult combine(const std::vector<ToolResult> &p_rounds) {
	ToolResult combined;
	std::vector<const Distribution *> latency, jitter;
	std::vector<double> rate_error, cpu, steal;
	for (const ToolResult &round : p_rounds) {
		if (!round.measured) {
			continue;
		}
		latency.push_back(&round.latency);
		jitter.push_back(&round.jitter);
		rate_error.push_back(round.rate_error_percent);
		cpu.push_back(round.cpu_fraction);
		steal.push_back(round.steal_percent);
		const uint64_t late = combined.stats.late_ticks + round.stats.late_ticks;
		const uint64_t missed = combined.stats.missed_deadlines + round.stats.missed_deadlines;
		const uint64_t ticks = combined.stats.ticks + round.stats.ticks;
		combined.stats = round.stats;
		combined.stats.late_ticks = late;
		combined.stats.missed_deadlines = missed;
		combined.stats.ticks = ticks;
		combined.worst_rate_error_percent = std::max(combined.worst_rate_error_percent, round.rate_error_percent);
	}
	if (latency.empty()) {
		combined.why_not = p_rounds.empty() ? "not run" : p_rounds.front().why_not;
		return combined;
	}
	combined.measured = true;
	combined.rounds = static_cast<int>(latency.size());
	combined.latency = combine_distributions(latency);
	combined.jitter = combine_distributions(jitter);
	combined.rate_error_percent = median(rate_error);
	combined.cpu_fraction = median(cpu);
	combined.steal_percent = median(steal);
	return combined;
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

// The old servo: SCHED_FIFO 50 and none of the other techniques.
ServoOptions baseline_options(double p_rate_hz) {
	ServoOptions options;
	options.rate_hz = p_rate_hz;
	options.realtime.priority = 50;
	options.realtime.lock_memory = false;
	options.realtime.hold_cpu_latency = false;
	options.realtime.cpu = PIN_NONE;
	options.realtime.prefault_stack_kb = 0;
	options.realtime.minimise_timer_slack = false;
	options.spin_ns = 0;
	return options;
}

std::vector<std::pair<std::string, ServoOptions>> technique_configurations(double p_rate_hz) {
	std::vector<std::pair<std::string, ServoOptions>> configurations;
	const ServoOptions base = baseline_options(p_rate_hz);
	configurations.emplace_back("before: SCHED_FIFO 50 only", base);
	ServoOptions o = base;
	o.realtime.lock_memory = true;
	configurations.emplace_back("+ mlockall", o);
	o = base;
	o.realtime.hold_cpu_latency = true;
	configurations.emplace_back("+ cpu_dma_latency 0", o);
	o = base;
	o.realtime.priority = 80;
	configurations.emplace_back("+ SCHED_FIFO 80", o);
	o = base;
	o.realtime.cpu = PIN_AUTO;
	configurations.emplace_back("+ pinned (last CPU)", o);
	o = base;
	o.realtime.prefault_stack_kb = 256;
	configurations.emplace_back("+ stack prefault 256 KiB", o);
	o = base;
	o.realtime.priority = 0;
	o.realtime.minimise_timer_slack = false;
	configurations.emplace_back("SCHED_OTHER, default timer slack", o);
	o.realtime.minimise_timer_slack = true;
	configurations.emplace_back("SCHED_OTHER + timer slack 1 ns", o);
	ServoOptions defaults;
	defaults.rate_hz = p_rate_hz;
	for (int64_t spin_us : { 0, 10, 25, 50, 100 }) {
		ServoOptions spun = defaults;
		spun.spin_ns = spin_us * 1000;
		configurations.emplace_back("defaults, spin " + std::to_string(spin_us) + " us", spun);
	}
	configurations.emplace_back("defaults (as shipped)", defaults);
	return configurations;
}

void print_distribution_row(const char *p_label, const Distribution &p_servo, const Distribution &p_cyclic) {
	std::printf("  %-14s servo %7.1f %7.1f %7.1f %8.1f | cyclictest ", p_label, p_servo.p50 * US, p_servo.p99 * US,
			p_servo.p999 * US, p_servo.max * US);
	if (!p_cyclic.measured) {
		std::printf("%7s %7s %7s %8s | ratio p99 -, p99.9 -\n", "-", "-", "-", "-");
		return;
	}
	const double r99 = p_cyclic.p99 > 0.0 ? p_servo.p99 / p_cyclic.p99 : 0.0;
	const double r999 = p_cyclic.p999 > 0.0 ? p_servo.p999 / p_cyclic.p999 : 0.0;
	std::printf("%7.1f %7.1f %7.1f %8.1f | ratio p99 %.2f, p99.9 %.2f %s\n", p_cyclic.p50 * US, p_cyclic.p99 * US,
			p_cyclic.p999 * US, p_cyclic.max * US, r99, r999,
			r99 <= GOAL_RATIO && r999 <= GOAL_RATIO ? "(goal <= 1.25 met)" : "(goal <= 1.25 MISSED)");
}

void print_condition(const ConditionResult &p_result) {
	std::printf("\n[%s] %s\n", p_result.name.c_str(), p_result.detail.c_str());
	if (!p_result.measured) {
		std::printf("  not measured: %s\n", p_result.why_not.c_str());
		return;
	}
	const ServoStats &s = p_result.servo.stats;
	std::printf("  servo: %s prio %d, mlock %s, cpu_dma_latency %s, cpu %d, stack %d KiB, spin %.0f us; "
				"rate error %.4f %% (median; worst round %.4f %%; goal <= %.2f %% %s), CPU %.1f %% of a core, "
				"late %llu, missed %llu over %llu ticks\n",
			scheduler_kind_name(s.scheduler), s.realtime_priority, s.memory_locked ? "yes" : "no",
			s.cpu_latency_held ? "held" : "no", s.pinned_cpu, s.stack_prefaulted_kb, s.spin_s * US,
			p_result.servo.rate_error_percent, p_result.servo.worst_rate_error_percent, RATE_GOAL_PERCENT,
			p_result.servo.rate_error_percent <= RATE_GOAL_PERCENT ? "met" : "MISSED", 100.0 * p_result.servo.cpu_fraction,
			static_cast<unsigned long long>(s.late_ticks), static_cast<unsigned long long>(s.missed_deadlines),
			static_cast<unsigned long long>(s.ticks));
	if (!p_result.cyclictest.measured) {
		std::printf("  cyclictest not measured: %s\n", p_result.cyclictest.why_not.c_str());
	} else {
		std::printf("  cyclictest: -m -p %d -i %lld (mlockall, cpu_dma_latency 0 while it runs)\n", p_result.cyclictest_priority,
				std::llround(1e6 / s.nominal_rate_hz));
	}
	std::printf("  CPU time stolen by the hypervisor (median): %.2f %% during the servo's runs, %.2f %% during cyclictest's\n",
			p_result.servo.steal_percent, p_result.cyclictest.steal_percent);
	std::printf("  %-14s       %7s %7s %7s %8s |            %7s %7s %7s %8s   (us)\n", "", "p50", "p99", "p99.9", "max", "p50",
			"p99", "p99.9", "max");
	print_distribution_row("wake latency", p_result.servo.latency, p_result.cyclictest.latency);
	print_distribution_row("period jitter", p_result.servo.jitter, p_result.cyclictest.jitter);
}

void print_techniques(const ConditionResult &p_result) {
	if (p_result.techniques.empty()) {
		return;
	}
	std::printf("\n  Techniques [%s], %s; wake latency and period jitter p50 / p99 / p99.9 / max in us, ratio to "
				"cyclictest's p99 / p99.9 in this condition\n",
			p_result.name.c_str(), p_result.detail.c_str());
	const Distribution &cl = p_result.cyclictest.latency;
	const Distribution &cj = p_result.cyclictest.jitter;
	for (const auto &[label, r] : p_result.techniques) {
		const double lr99 = cl.measured && cl.p99 > 0.0 ? r.latency.p99 / cl.p99 : 0.0;
		const double lr999 = cl.measured && cl.p999 > 0.0 ? r.latency.p999 / cl.p999 : 0.0;
		const double jr99 = cj.measured && cj.p99 > 0.0 ? r.jitter.p99 / cj.p99 : 0.0;
		const double jr999 = cj.measured && cj.p999 > 0.0 ? r.jitter.p999 / cj.p999 : 0.0;
		std::printf("  %-34s lat %6.1f %6.1f %7.1f %8.1f (x%.2f x%.2f)  jit %6.1f %6.1f %7.1f %8.1f (x%.2f x%.2f)  CPU "
					"%5.1f %%  rate err %.4f %% (worst %.4f %%)\n",
				label.c_str(), r.latency.p50 * US, r.latency.p99 * US, r.latency.p999 * US, r.latency.max * US, lr99, lr999,
				r.jitter.p50 * US, r.jitter.p99 * US, r.jitter.p999 * US, r.jitter.max * US, jr99, jr999,
				100.0 * r.cpu_fraction, r.rate_error_percent, r.worst_rate_error_percent);
	}
}

void write_distribution(std::ofstream &r_out, const Distribution &p_distribution) {
	r_out << "{\"measured\": " << (p_distribution.measured ? "true" : "false") << ", \"p50\": " << p_distribution.p50 * US
		  << ", \"p99\": " << p_distribution.p99 * US << ", \"p999\": " << p_distribution.p999 * US
		  << ", \"max\": " << p_distribution.max * US << ", \"count\": " << p_distribution.count << "}";
}

void write_tool(std::ofstream &r_out, const ToolResult &p_tool) {
	r_out << "{\"measured\": " << (p_tool.measured ? "true" : "false") << ", \"why_not\": \"" << p_tool.why_not
		  << "\", \"latency_us\": ";
	write_distribution(r_out, p_tool.latency);
	r_out << ", \"jitter_us\": ";
	write_distribution(r_out, p_tool.jitter);
	const ServoStats &s = p_tool.stats;
	r_out << ", \"rounds\": " << p_tool.rounds << ", \"steal_percent\": " << p_tool.steal_percent
		  << ", \"rate_error_percent\": " << p_tool.rate_error_percent
		  << ", \"worst_rate_error_percent\": " << p_tool.worst_rate_error_percent << ", \"cpu_fraction\": " << p_tool.cpu_fraction
		  << ", \"scheduler\": \"" << scheduler_kind_name(s.scheduler) << "\", \"priority\": " << s.realtime_priority
		  << ", \"memory_locked\": " << (s.memory_locked ? "true" : "false")
		  << ", \"cpu_latency_held\": " << (s.cpu_latency_held ? "true" : "false") << ", \"pinned_cpu\": " << s.pinned_cpu
		  << ", \"stack_prefaulted_kb\": " << s.stack_prefaulted_kb << ", \"spin_us\": " << s.spin_s * US
		  << ", \"late_ticks\": " << s.late_ticks << ", \"missed_deadlines\": " << s.missed_deadlines << "}";
}

bool write_json(const std::string &p_path, const std::vector<LatencyResult> &p_latencies,
		const std::vector<ConditionResult> &p_results) {
	std::error_code ignored;
	const std::filesystem::path path(p_path);
	if (path.has_parent_path()) {
		std::filesystem::create_directories(path.parent_path(), ignored);
	}
	std::ofstream out(p_path);
	if (!out) {
		std::fprintf(stderr, "cannot write %s\n", p_path.c_str());
		return false;
	}
	out << "{\n  \"goal_ratio\": " << GOAL_RATIO << ", \"rate_goal_percent\": " << RATE_GOAL_PERCENT
		<< ",\n  \"latency_ticks\": [";
	for (size_t l = 0; l < p_latencies.size(); ++l) {
		const LatencyResult &r = p_latencies[l];
		out << (l ? ", " : "") << "{\"mode\": \"" << r.mode << "\", \"hand\": \"" << r.hand
			<< "\", \"first_change\": " << r.first_change_ticks << ", \"settle_90\": " << r.settle_90_ticks
			<< ", \"force_before_n\": " << r.force_before_n << ", \"force_after_n\": " << r.force_after_n << "}";
	}
	out << "],\n  \"conditions\": [";
	for (size_t c = 0; c < p_results.size(); ++c) {
		const ConditionResult &r = p_results[c];
		out << (c ? ",\n    " : "\n    ") << "{\"name\": \"" << r.name << "\", \"detail\": \"" << r.detail
			<< "\", \"measured\": " << (r.measured ? "true" : "false") << ", \"why_not\": \"" << r.why_not
			<< "\", \"cyclictest_priority\": " << r.cyclictest_priority << ", \"servo\": ";
		write_tool(out, r.servo);
		out << ", \"cyclictest\": ";
		write_tool(out, r.cyclictest);
		out << ", \"techniques\": [";
		for (size_t t = 0; t < r.techniques.size(); ++t) {
			out << (t ? ", " : "") << "{\"name\": \"" << r.techniques[t].first << "\", \"result\": ";
			write_tool(out, r.techniques[t].second);
			out << "}";
		}
		out << "]}";
	}
	out << "\n  ]\n}\n";
	return static_cast<bool>(out);
}

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
		} else {
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
				"[--techniques]\n",
				p_argv[0]);
		return 1;
	}
	const ServoOptions shipped;
	std::printf("haptics_rt_bench: the servo (shipped defaults, simulated device, 50 Hz producer) next to cyclictest "
				"at %.0f Hz: %d rounds of %.1f s each per condition, order rotating; %u hardware threads\n",
			shipped.rate_hz, options.rounds, options.seconds, std::thread::hardware_concurrency());
	std::printf("wake latency = wake-up time - deadline (cyclictest's measure); period jitter = |period - nominal|; "
				"1 us bins; p50/p99/p99.9 = median over the rounds, max = largest; ratio = servo / cyclictest, goal <= %.2f\n",
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
		// Job 0: the servo as shipped; job 1: cyclictest; then the techniques.
		std::vector<std::pair<std::string, ServoOptions>> jobs = { { "servo", shipped } };
		jobs.emplace_back("cyclictest", shipped);
		if (options.techniques) {
			for (const auto &configuration : technique_configurations(shipped.rate_hz)) {
				jobs.push_back(configuration);
			}
		}
		std::printf("\n[%s] measuring: %d rounds of %zu measurements x %.1f s...\n", name.c_str(), options.rounds, jobs.size(),
				options.seconds);
		std::fflush(stdout);
		std::vector<std::vector<ToolResult>> runs(jobs.size());
		// cyclictest runs at the priority the servo gets here (none when SCHED_FIFO is refused).
		int32_t priority = 0;
		std::thread([&] { priority = try_make_current_thread_realtime(shipped.realtime.priority).priority; }).join();
		for (int round = 0; round < options.rounds; ++round) {
			for (size_t k = 0; k < jobs.size(); ++k) {
				const size_t job = (k + static_cast<size_t>(round)) % jobs.size();
				runs[job].push_back(job == 1 ? run_cyclictest(priority, shipped.rate_hz, options.seconds)
											 : run_servo(jobs[job].second, options.seconds));
			}
		}
		result.servo = combine(runs[0]);
		result.cyclictest_priority = result.servo.stats.realtime_priority;
		result.cyclictest = combine(runs[1]);
		for (size_t job = 2; job < jobs.size(); ++job) {
			result.techniques.emplace_back(jobs[job].first, combine(runs[job]));
		}
		if (render_load) {
			result.detail = render_load->describe(); // Now with its restarts.
			render_load->stop();
		}
		result.measured = true;
		print_condition(result);
		print_techniques(result);
		std::fflush(stdout);
		results.push_back(result);
	}
	if (!write_json(options.json_path, latencies, results)) {
		return 1;
	}
	std::printf("\nwrote %s\n", options.json_path.c_str());
	return 0;
}
