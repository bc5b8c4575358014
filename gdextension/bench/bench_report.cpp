// The benchmark's report: a side-by-side table (deadline loop vs naive sleep_for loop,
// same run) with ratios and the targets, and the same figures as JSON.

#include "bench_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace haptics::bench {

namespace {

constexpr double US = 1e6;

struct Row {
	const char *label;
	double deadline;
	double naive;
	const char *target; // "" when there is no target.
	bool met;
};

double rate_error_percent(const ServoStats &p_stats) {
	return p_stats.nominal_rate_hz > 0.0 ? 100.0 * std::abs(p_stats.achieved_rate_hz - p_stats.nominal_rate_hz) / p_stats.nominal_rate_hz : 0.0;
}

std::vector<Row> rows(const LoopResult &p_deadline, const LoopResult &p_naive) {
	const ServoStats &d = p_deadline.stats;
	const ServoStats &n = p_naive.stats;
	return {
		{ "achieved rate (Hz)", d.achieved_rate_hz, n.achieved_rate_hz, "", true },
		{ "rate error (%)", rate_error_percent(d), rate_error_percent(n), "<= 0.1", rate_error_percent(d) <= 0.1 },
		{ "period mean (us)", d.period_mean_s * US, n.period_mean_s * US, "", true },
		{ "period p50 (us)", d.period_p50_s * US, n.period_p50_s * US, "", true },
		{ "period p99 (us)", d.period_p99_s * US, n.period_p99_s * US, "", true },
		{ "period p99.9 (us)", d.period_p999_s * US, n.period_p999_s * US, "", true },
		{ "period max (us)", d.period_max_s * US, n.period_max_s * US, "", true },
		{ "|period - nominal| p50 (us)", d.jitter_p50_s * US, n.jitter_p50_s * US, "", true },
		{ "|period - nominal| p99 (us)", d.jitter_p99_s * US, n.jitter_p99_s * US, "<= 50", d.jitter_p99_s * US <= 50.0 },
		{ "|period - nominal| p99.9 (us)", d.jitter_p999_s * US, n.jitter_p999_s * US, "", true },
		{ "late ticks (> 0.5 period)", static_cast<double>(d.late_ticks), static_cast<double>(n.late_ticks), "", true },
		{ "missed deadlines (skipped)", static_cast<double>(d.missed_deadlines), static_cast<double>(n.missed_deadlines), "", true },
		{ "tick cost p50 (us)", d.tick_cost_p50_s * US, n.tick_cost_p50_s * US, "<= 2", d.tick_cost_p50_s * US <= 2.0 },
		{ "tick cost p99 (us)", d.tick_cost_p99_s * US, n.tick_cost_p99_s * US, "", true },
		{ "tick cost max (us)", d.tick_cost_max_s * US, n.tick_cost_max_s * US, "", true },
		{ "ticks", static_cast<double>(d.ticks), static_cast<double>(n.ticks), "", true },
		{ "frames received", static_cast<double>(d.frames_received), static_cast<double>(n.frames_received), "", true },
		{ "transient drops", static_cast<double>(d.transient_drops), static_cast<double>(n.transient_drops), "", true },
		{ "telemetry drops", static_cast<double>(d.telemetry_drops), static_cast<double>(n.telemetry_drops), "", true },
	};
}

} // namespace

void print_report(const LoopResult &p_deadline, const LoopResult &p_naive, const std::vector<MicroResult> &p_micro) {
	std::printf("\nServo loop, %.0f Hz nominal, %.1f s each, simulated device, 50 Hz producer thread\n",
			p_deadline.stats.nominal_rate_hz, p_deadline.duration_s);
	std::printf("scheduler: deadline loop %s (prio %d), naive loop %s (prio %d)\n\n",
			scheduler_kind_name(p_deadline.stats.scheduler), p_deadline.stats.realtime_priority,
			scheduler_kind_name(p_naive.stats.scheduler), p_naive.stats.realtime_priority);
	std::printf("%-30s %14s %14s %10s   %-8s %s\n", "metric", "deadline", "naive sleep", "naive/dl", "target", "");
	for (const Row &row : rows(p_deadline, p_naive)) {
		char ratio[32] = "-";
		if (row.deadline != 0.0) {
			std::snprintf(ratio, sizeof(ratio), "%.2f", row.naive / row.deadline);
		}
		std::printf("%-30s %14.3f %14.3f %10s   %-8s %s\n", row.label, row.deadline, row.naive, ratio, row.target,
				row.target[0] ? (row.met ? "met" : "MISSED") : "");
	}
	std::printf("\nTick-cost micro-benchmarks (per call, median / p99 over batches)\n");
	for (const MicroResult &micro : p_micro) {
		std::printf("  %-66s %8.1f ns %8.1f ns\n", micro.name.c_str(), micro.median_ns, micro.p99_ns);
	}
	std::printf("\nProducer: deadline run %llu frames, %llu impacts, %llu telemetry samples drained; "
				"naive run %llu frames, %llu impacts, %llu samples\n",
			static_cast<unsigned long long>(p_deadline.frames_submitted),
			static_cast<unsigned long long>(p_deadline.impacts_pushed),
			static_cast<unsigned long long>(p_deadline.telemetry_drained),
			static_cast<unsigned long long>(p_naive.frames_submitted), static_cast<unsigned long long>(p_naive.impacts_pushed),
			static_cast<unsigned long long>(p_naive.telemetry_drained));
}

void print_proxy_report(const std::vector<ProxyBenchResult> &p_proxy) {
	std::printf("\nFinite proxy update cost (per update; grid vs brute force, same run, same paths)\n");
	std::printf("%8s %6s %9s %10s %10s %11s %11s %9s %9s %7s %8s %s\n", "walls", "path", "grid", "grid p50",
			"grid p99", "brute p50", "brute p99", "p50 x", "p99 x", "sweeps", "contact", "same path");
	for (const ProxyBenchResult &r : p_proxy) {
		char grid[32];
		std::snprintf(grid, sizeof(grid), "%dx%d", r.grid_columns, r.grid_rows);
		std::printf("%8zu %6s %9s %7.0f ns %7.0f ns %8.0f ns %8.0f ns %8.1fx %8.1fx %7.2f %7.0f%% %s\n", r.segments,
				r.path.c_str(), grid, r.grid_p50_ns, r.grid_p99_ns, r.brute_p50_ns, r.brute_p99_ns,
				r.brute_p50_ns / r.grid_p50_ns, r.brute_p99_ns / r.grid_p99_ns, r.mean_sweeps, 100.0 * r.contact_fraction,
				r.identical ? "yes" : "NO");
	}
	for (const char *path : { "sweep", "local" }) {
		const ProxyBenchResult *fewest = nullptr;
		const ProxyBenchResult *most = nullptr;
		for (const ProxyBenchResult &r : p_proxy) {
			if (r.path == path) {
				fewest = fewest ? fewest : &r;
				most = &r;
			}
		}
		if (fewest && most != fewest) {
			std::printf("%s path, p50 at %zu walls / p50 at %zu walls: grid %.2f (flat = 1), brute force %.1f\n", path,
					most->segments, fewest->segments, most->grid_p50_ns / fewest->grid_p50_ns,
					most->brute_p50_ns / fewest->brute_p50_ns);
		}
	}
}

namespace {

void write_proxy_array(std::ofstream &r_out, const std::vector<ProxyBenchResult> &p_proxy) {
	r_out << "[";
	for (size_t p = 0; p < p_proxy.size(); ++p) {
		const ProxyBenchResult &r = p_proxy[p];
		r_out << (p ? ",\n    " : "\n    ") << "{\"segments\": " << r.segments << ", \"path\": \"" << r.path
			  << "\", \"grid_cells\": [" << r.grid_columns << ", " << r.grid_rows << "]"
			  << ", \"grid_ns\": {\"p50\": " << r.grid_p50_ns << ", \"p99\": " << r.grid_p99_ns
			  << ", \"max\": " << r.grid_max_ns << "}, \"brute_force_ns\": {\"p50\": " << r.brute_p50_ns
			  << ", \"p99\": " << r.brute_p99_ns << ", \"max\": " << r.brute_max_ns << "}"
			  << ", \"ratio_brute_over_grid\": {\"p50\": " << r.brute_p50_ns / r.grid_p50_ns
			  << ", \"p99\": " << r.brute_p99_ns / r.grid_p99_ns << "}, \"mean_sweeps\": " << r.mean_sweeps
			  << ", \"contact_fraction\": " << r.contact_fraction
			  << ", \"identical_paths\": " << (r.identical ? "true" : "false") << "}";
	}
	r_out << "]";
}

} // namespace

bool write_json(const std::string &p_path, const LoopResult *p_deadline_loop, const LoopResult *p_naive_loop,
		const std::vector<MicroResult> &p_micro, const std::vector<ProxyBenchResult> &p_proxy) {
	std::error_code error;
	const std::filesystem::path path(p_path);
	if (path.has_parent_path()) {
		std::filesystem::create_directories(path.parent_path(), error);
	}
	std::ofstream out(p_path);
	if (!out) {
		std::fprintf(stderr, "cannot write %s\n", p_path.c_str());
		return false;
	}
	if (p_deadline_loop == nullptr || p_naive_loop == nullptr) {
		out << "{\n  \"proxy\": ";
		write_proxy_array(out, p_proxy);
		out << "\n}\n";
		return static_cast<bool>(out);
	}
	const LoopResult &p_deadline = *p_deadline_loop;
	const LoopResult &p_naive = *p_naive_loop;
	const auto loop = [&out](const LoopResult &p_result) {
		const ServoStats &s = p_result.stats;
		out << "{\"scheduler\": \"" << scheduler_kind_name(s.scheduler) << "\", \"priority\": " << s.realtime_priority
			<< ", \"duration_s\": " << p_result.duration_s << ", \"nominal_rate_hz\": " << s.nominal_rate_hz
			<< ", \"achieved_rate_hz\": " << s.achieved_rate_hz << ", \"rate_error_percent\": " << rate_error_percent(s)
			<< ", \"ticks\": " << s.ticks << ", \"period_us\": {\"mean\": " << s.period_mean_s * US
			<< ", \"p50\": " << s.period_p50_s * US << ", \"p99\": " << s.period_p99_s * US
			<< ", \"p999\": " << s.period_p999_s * US << ", \"max\": " << s.period_max_s * US << "}"
			<< ", \"jitter_us\": {\"p50\": " << s.jitter_p50_s * US << ", \"p99\": " << s.jitter_p99_s * US
			<< ", \"p999\": " << s.jitter_p999_s * US << ", \"max\": " << s.jitter_max_s * US << "}"
			<< ", \"late_ticks\": " << s.late_ticks << ", \"missed_deadlines\": " << s.missed_deadlines
			<< ", \"tick_cost_us\": {\"p50\": " << s.tick_cost_p50_s * US << ", \"p99\": " << s.tick_cost_p99_s * US
			<< ", \"max\": " << s.tick_cost_max_s * US << "}"
			<< ", \"frames_submitted\": " << p_result.frames_submitted << ", \"frames_received\": " << s.frames_received
			<< ", \"impacts_pushed\": " << p_result.impacts_pushed << ", \"transient_drops\": " << s.transient_drops
			<< ", \"telemetry_drained\": " << p_result.telemetry_drained << ", \"telemetry_drops\": " << s.telemetry_drops
			<< "}";
	};
	const ServoStats &d = p_deadline.stats;
	const ServoStats &n = p_naive.stats;
	const auto ratio = [](double p_naive_value, double p_deadline_value) {
		return p_deadline_value != 0.0 ? p_naive_value / p_deadline_value : 0.0;
	};
	out << "{\n  \"deadline\": ";
	loop(p_deadline);
	out << ",\n  \"naive\": ";
	loop(p_naive);
	out << ",\n  \"ratios_naive_over_deadline\": {\"period_p99\": " << ratio(n.period_p99_s, d.period_p99_s)
		<< ", \"period_max\": " << ratio(n.period_max_s, d.period_max_s)
		<< ", \"jitter_p99\": " << ratio(n.jitter_p99_s, d.jitter_p99_s)
		<< ", \"rate_error\": " << ratio(rate_error_percent(n), rate_error_percent(d))
		<< ", \"tick_cost_p50\": " << ratio(n.tick_cost_p50_s, d.tick_cost_p50_s) << "}";
	out << ",\n  \"targets_deadline\": {\"rate_within_0_1_percent\": " << (rate_error_percent(d) <= 0.1 ? "true" : "false")
		<< ", \"jitter_p99_le_50us\": " << (d.jitter_p99_s * US <= 50.0 ? "true" : "false")
		<< ", \"tick_cost_p50_le_2us\": " << (d.tick_cost_p50_s * US <= 2.0 ? "true" : "false") << "}";
	out << ",\n  \"micro_ns\": [";
	for (size_t m = 0; m < p_micro.size(); ++m) {
		out << (m ? ", " : "") << "{\"name\": \"" << p_micro[m].name << "\", \"median\": " << p_micro[m].median_ns
			<< ", \"p99\": " << p_micro[m].p99_ns << "}";
	}
	out << "],\n  \"proxy\": ";
	write_proxy_array(out, p_proxy);
	out << "\n}\n";
	return static_cast<bool>(out);
}

} // namespace haptics::bench
