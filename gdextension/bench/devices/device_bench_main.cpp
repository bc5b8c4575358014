// haptics_device_bench [--seconds S] [--json PATH]: runs every registered backend benchmark
// (device_bench.h) and prints one table; the same figures go to JSON (.bench/devices.json).

#include "device_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace haptics::bench {

DeviceBenchRegistrar::DeviceBenchRegistrar(const char *p_name, DeviceBenchFunction p_function) {
	device_benches().push_back({ p_name, p_function });
}

std::vector<DeviceBenchEntry> &device_benches() {
	static std::vector<DeviceBenchEntry> entries;
	return entries;
}

double percentile(std::vector<double> p_values, double p_percent) {
	if (p_values.empty()) {
		return 0.0;
	}
	std::sort(p_values.begin(), p_values.end());
	const double rank = p_percent / 100.0 * static_cast<double>(p_values.size() - 1);
	return p_values[static_cast<size_t>(std::lround(rank))];
}

} // namespace haptics::bench

int main(int p_argc, char **p_argv) {
	using namespace haptics::bench;
	double seconds = 1.0;
	std::string json_path = ".bench/devices.json";
	for (int a = 1; a < p_argc; ++a) {
		const std::string arg = p_argv[a];
		if (arg == "--seconds" && a + 1 < p_argc) {
			seconds = std::atof(p_argv[++a]);
		} else if (arg == "--json" && a + 1 < p_argc) {
			json_path = p_argv[++a];
		} else {
			std::fprintf(stderr, "usage: %s [--seconds S] [--json PATH]\n", p_argv[0]);
			return 2;
		}
	}
	std::vector<DeviceBenchEntry> entries = device_benches();
	std::sort(entries.begin(), entries.end(),
			[](const DeviceBenchEntry &a, const DeviceBenchEntry &b) { return std::string(a.name) < b.name; });
	std::vector<DeviceBenchResult> results;
	for (const DeviceBenchEntry &entry : entries) {
		DeviceBenchResult result = entry.function(seconds);
		result.backend = entry.name;
		results.push_back(result);
	}

	std::printf("\nDevice backends against scripted transports (%.1f s each; our side only, no bus)\n\n", seconds);
	std::printf("%-12s %12s %12s %12s %12s %14s %10s  %s\n", "backend", "tick p50 us", "tick p99 us", "encode p50", "encode p99",
			"max updates/s", "bytes/upd", "real-device limit");
	for (const DeviceBenchResult &r : results) {
		std::printf("%-12s %12.3f %12.3f %12.3f %12.3f %14.0f %10.1f  %s\n", r.backend.c_str(), r.tick_p50_us, r.tick_p99_us,
				r.encode_p50_us, r.encode_p99_us, r.max_update_rate_hz, r.bytes_per_update, r.note.c_str());
	}

	const std::filesystem::path path(json_path);
	if (path.has_parent_path()) {
		std::error_code error;
		std::filesystem::create_directories(path.parent_path(), error);
	}
	std::ofstream out(json_path);
	if (!out) {
		std::fprintf(stderr, "cannot write %s\n", json_path.c_str());
		return 1;
	}
	out << "{\n  \"seconds\": " << seconds << ",\n  \"backends\": [";
	for (size_t i = 0; i < results.size(); ++i) {
		const DeviceBenchResult &r = results[i];
		out << (i ? "," : "") << "\n    {\"backend\": \"" << r.backend << "\", \"tick_p50_us\": " << r.tick_p50_us
			<< ", \"tick_p99_us\": " << r.tick_p99_us << ", \"encode_p50_us\": " << r.encode_p50_us
			<< ", \"encode_p99_us\": " << r.encode_p99_us << ", \"max_update_rate_hz\": " << r.max_update_rate_hz
			<< ", \"bytes_per_update\": " << r.bytes_per_update << "}";
	}
	out << "\n  ]\n}\n";
	std::printf("\nwrote %s\n", json_path.c_str());
	return 0;
}
