#include "rt_report.h"

#include "core/base/realtime.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace haptics::bench {

namespace {

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

void write_distribution(std::ofstream &r_out, const Distribution &p_distribution) {
	r_out << "{\"measured\": " << (p_distribution.measured ? "true" : "false") << ", \"p50\": " << p_distribution.p50 * US
		  << ", \"p99\": " << p_distribution.p99 * US << ", \"p999\": " << p_distribution.p999 * US
		  << ", \"max\": " << p_distribution.max * US << ", \"count\": " << p_distribution.count
		  << ", \"pooled\": " << (p_distribution.pooled ? "true" : "false") << ", \"p999_low\": " << p_distribution.p999_low * US
		  << ", \"p999_high\": " << p_distribution.p999_high * US << "}";
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
		  << ", \"spin_learned\": " << (s.spin_learned ? "true" : "false")
		  << ", \"late_ticks\": " << s.late_ticks << ", \"missed_deadlines\": " << s.missed_deadlines << "}";
}

} // namespace

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
	const Distribution &servo = p_result.servo.latency;
	const Distribution &cyclic = p_result.cyclictest.latency;
	if (servo.pooled) {
		std::printf("  %-14s servo %llu ticks pooled, p99.9's 95 %% interval [%.1f-%.1f] | cyclictest %llu, [%.1f-%.1f]\n",
				"", static_cast<unsigned long long>(servo.count), servo.p999_low * US, servo.p999_high * US,
				static_cast<unsigned long long>(cyclic.count), cyclic.p999_low * US, cyclic.p999_high * US);
	}
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
		if (!r.measured) {
			std::printf("  %-46s not measured: %s\n", label.c_str(), r.why_not.c_str());
			continue;
		}
		const double lr99 = cl.measured && cl.p99 > 0.0 ? r.latency.p99 / cl.p99 : 0.0;
		const double lr999 = cl.measured && cl.p999 > 0.0 ? r.latency.p999 / cl.p999 : 0.0;
		const double jr99 = cj.measured && cj.p99 > 0.0 ? r.jitter.p99 / cj.p99 : 0.0;
		const double jr999 = cj.measured && cj.p999 > 0.0 ? r.jitter.p999 / cj.p999 : 0.0;
		std::printf("  %-46s lat %6.1f %6.1f %7.1f %8.1f (x%.2f x%.2f)  jit %6.1f %6.1f %7.1f %8.1f (x%.2f x%.2f)  CPU "
					"%5.1f %%  rate err %.4f %% (worst %.4f %%)\n",
				label.c_str(), r.latency.p50 * US, r.latency.p99 * US, r.latency.p999 * US, r.latency.max * US, lr99, lr999,
				r.jitter.p50 * US, r.jitter.p99 * US, r.jitter.p999 * US, r.jitter.max * US, jr99, jr999,
				100.0 * r.cpu_fraction, r.rate_error_percent, r.worst_rate_error_percent);
	}
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

} // namespace haptics::bench
