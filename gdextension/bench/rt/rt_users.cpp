#include "rt_users.h"

#include "rt_jobs.h"
#include "rt_processes.h"

#include <pwd.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <type_traits>
#include <vector>

namespace haptics::bench {

namespace {

// Parent and child are the same binary: the record is its memory, behind a tag that catches a
// child that printed anything else.
constexpr char TAG[8] = { 'H', 'R', 'T', 'C', 'H', 'I', 'L', 'D' };
static_assert(std::is_trivially_copyable_v<ServoChildReport>, "the child's report is copied as bytes");

std::string self_path() {
	char path[4096];
	const ssize_t length = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
	return length > 0 ? std::string(path, static_cast<size_t>(length)) : std::string();
}

} // namespace

bool write_child_report(const ServoChildReport &p_report) {
	return std::fwrite(TAG, sizeof(TAG), 1, stdout) == 1 && std::fwrite(&p_report, sizeof(p_report), 1, stdout) == 1 &&
			std::fflush(stdout) == 0;
}

bool run_servo_child(const std::string &p_user, const std::string &p_bus, const ServoOptions &p_options,
		double p_seconds, ServoChildReport &r_report, std::string &r_error) {
	const std::string self = self_path();
	if (self.empty()) {
		r_error = "cannot find this program's own path";
		return false;
	}
	const passwd *account = ::getpwnam(p_user.c_str());
	if (account == nullptr) {
		r_error = "no user '" + p_user + "'";
		return false;
	}
	std::vector<std::string> argv = { "setpriv", "--reuid=" + std::to_string(account->pw_uid),
		"--regid=" + std::to_string(account->pw_gid), "--clear-groups",
		"--inh-caps=-all", "env", "-i", "DBUS_SYSTEM_BUS_ADDRESS=" + (p_bus.empty() ? std::string(NO_SYSTEM_BUS) : p_bus),
		"PATH=/usr/bin:/bin", self, "--servo-child", std::to_string(p_seconds) };
	const std::vector<std::string> options = user_child_arguments(p_options);
	argv.insert(argv.end(), options.begin(), options.end());
	std::string output;
	if (!run_and_capture(argv, p_seconds * 3.0 + 30.0, output, r_error)) {
		r_error = "as " + p_user + ": " + r_error;
		return false;
	}
	if (output.size() != sizeof(TAG) + sizeof(ServoChildReport) || std::memcmp(output.data(), TAG, sizeof(TAG)) != 0) {
		r_error = "as " + p_user + ": the child printed " + std::to_string(output.size()) + " bytes, not its report";
		return false;
	}
	std::memcpy(&r_report, output.data() + sizeof(TAG), sizeof(ServoChildReport));
	return true;
}

void print_user_comparison(const ConditionResult &p_result) {
	const Distribution &root = p_result.servo.latency;
	bool header = false;
	for (const auto &[label, r] : p_result.techniques) {
		const bool as_user = label.rfind("as ", 0) == 0;
		if ((!as_user && label.rfind("root, ", 0) != 0) || !r.measured || !root.measured) {
			continue;
		}
		if (!header) {
			std::printf("\n  The servo as an ordinary user [%s] against root's (SCHED_%s %d) in the same rounds: wake latency "
						"p99 / p99.9 in us\n",
					p_result.name.c_str(), p_result.servo.stats.scheduler == SchedulerKind::REALTIME_FIFO ? "FIFO" : "OTHER",
					p_result.servo.stats.realtime_priority);
			std::printf("  %-46s %8.1f %8.1f            CPU %4.1f %%\n", "root (as shipped)", root.p99 * US, root.p999 * US,
					100.0 * p_result.servo.cpu_fraction);
			header = true;
		}
		const double r99 = root.p99 > 0.0 ? r.latency.p99 / root.p99 : 0.0;
		const double r999 = root.p999 > 0.0 ? r.latency.p999 / root.p999 : 0.0;
		std::printf("  %-46s %8.1f %8.1f  x%.2f x%.2f  CPU %4.1f %%  (%s %d%s, RealtimeKit: %s)\n", label.c_str(),
				r.latency.p99 * US, r.latency.p999 * US, r99, r999, 100.0 * r.cpu_fraction,
				scheduler_kind_name(r.stats.scheduler), r.stats.realtime_priority,
				r.stats.cpu_latency_held ? ", cpu_dma_latency held" : "", rtkit_outcome_name(r.stats.realtime_kit.outcome));
		if (r.stats.realtime_kit.rttime_usec > 0) {
			// RLIMIT_RTTIME counts CPU time between sleeps: the spin and the tick.
			const double run_us = (r.stats.spin_s + r.stats.tick_cost_max_s) * US;
			std::printf("  %-46s longest run without sleeping <= %.0f us (spin + slowest tick) of RLIMIT_RTTIME %.0f ms: "
						"x%.0f headroom\n",
					"", run_us, static_cast<double>(r.stats.realtime_kit.rttime_usec) / 1000.0,
					static_cast<double>(r.stats.realtime_kit.rttime_usec) / run_us);
		}
	}
}

} // namespace haptics::bench
