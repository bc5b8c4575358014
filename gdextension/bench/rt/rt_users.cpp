#include "rt_users.h"

#include "rt_jobs.h"
#include "rt_processes.h"

#include "core/servo/wake_ahead.h"

#include <pwd.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <vector>

namespace haptics::bench {

namespace {

// Parent and child are the same binary: the record is its memory, behind a tag that catches a
// child that printed anything else.
constexpr char TAG[8] = { 'H', 'R', 'T', 'C', 'H', 'I', 'L', 'D' };
constexpr const char *LATENCY_FILE = "/dev/cpu_dma_latency";
static_assert(std::is_trivially_copyable_v<ServoChildReport>, "the child's report is copied as bytes");

std::string self_path() {
	char path[4096];
	const ssize_t length = ::readlink("/proc/self/exe", path, sizeof(path) - 1);
	return length > 0 ? std::string(path, static_cast<size_t>(length)) : std::string();
}

// Gives p_user read and write access to /dev/cpu_dma_latency, or takes it back, with an ACL
// entry: what the udev rule's uaccess tag gives the logged-in user.
bool set_latency_access(const std::string &p_user, bool p_grant, std::string &r_error) {
	const std::vector<std::string> argv = p_grant
			? std::vector<std::string>{ "setfacl", "-m", "u:" + p_user + ":rw", LATENCY_FILE }
			: std::vector<std::string>{ "setfacl", "-x", "u:" + p_user, LATENCY_FILE };
	std::string ignored;
	if (!run_and_capture(argv, 10.0, ignored, r_error)) {
		r_error = std::string(p_grant ? "could not give " : "could not take back from ") + p_user + " " + LATENCY_FILE +
				": " + r_error;
		return false;
	}
	return true;
}

} // namespace

bool write_child_report(const ServoChildReport &p_report) {
	return std::fwrite(TAG, sizeof(TAG), 1, stdout) == 1 && std::fwrite(&p_report, sizeof(p_report), 1, stdout) == 1 &&
			std::fflush(stdout) == 0;
}

bool run_servo_child(const std::string &p_user, const std::string &p_bus, const ServoOptions &p_options,
		bool p_latency_access, double p_seconds, ServoChildReport &r_report, std::string &r_error) {
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
	if (p_latency_access && !set_latency_access(p_user, true, r_error)) {
		return false;
	}
	const bool ran = run_and_capture(argv, p_seconds * 3.0 + 30.0, output, r_error);
	std::string revoke_error;
	if (p_latency_access && !set_latency_access(p_user, false, revoke_error) && ran) {
		r_error = revoke_error;
		return false;
	}
	if (!ran) {
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
						"p99 / p99.9 [95 %% interval] in us, %s over %llu ticks of root's; ratios to root's; steal: the "
						"hypervisor's share of the CPUs while the row ran (host noise, not the servo's)\n",
					p_result.name.c_str(), p_result.servo.stats.scheduler == SchedulerKind::REALTIME_FIFO ? "FIFO" : "OTHER",
					p_result.servo.stats.realtime_priority, root.pooled ? "pooled" : "medians of rounds",
					static_cast<unsigned long long>(root.count));
			std::printf("  %-46s %8.1f %8.1f [%6.1f-%6.1f]               spin %3.0f us  CPU %4.1f %%  steal %.2f %%\n",
					"root (as shipped)", root.p99 * US, root.p999 * US, root.p999_low * US, root.p999_high * US,
					p_result.servo.stats.spin_s * US, 100.0 * p_result.servo.cpu_fraction, p_result.servo.steal_percent);
			header = true;
		}
		const double r99 = root.p99 > 0.0 ? r.latency.p99 / root.p99 : 0.0;
		const double r999 = root.p999 > 0.0 ? r.latency.p999 / root.p999 : 0.0;
		const ServoStats &s = r.stats;
		std::printf("  %-46s %8.1f %8.1f [%6.1f-%6.1f]  x%5.2f x%5.2f  spin %3.0f us%s  CPU %4.1f %%  steal %.2f %%  (%s "
					"%d%s, RealtimeKit: %s)\n",
				label.c_str(), r.latency.p99 * US, r.latency.p999 * US, r.latency.p999_low * US, r.latency.p999_high * US, r99,
				r999, s.spin_s * US, s.spin_learned ? " learned, last" : "", 100.0 * r.cpu_fraction, r.steal_percent,
				scheduler_kind_name(s.scheduler), s.realtime_priority, s.cpu_latency_held ? ", cpu_dma_latency held" : "",
				rtkit_outcome_name(s.realtime_kit.outcome));
		if (s.realtime_kit.rttime_usec > 0) {
			// RLIMIT_RTTIME counts CPU time between sleeps: the spin (at most its cap, when
			// learned) and the tick.
			const int64_t spin_ns = s.spin_learned ? wake_ahead_cap_ns(s.nominal_rate_hz, s.realtime_kit.rttime_usec)
												   : std::llround(s.spin_s * 1e9);
			const double run_us = static_cast<double>(spin_ns) / 1000.0 + s.tick_cost_max_s * US;
			std::printf("  %-46s longest run without sleeping <= %.0f us (%s + slowest tick) of RLIMIT_RTTIME %.0f ms: "
						"x%.0f headroom\n",
					"", run_us, s.spin_learned ? "the most the learned spin may grow to" : "the spin",
					static_cast<double>(s.realtime_kit.rttime_usec) / 1000.0,
					static_cast<double>(s.realtime_kit.rttime_usec) / run_us);
		}
	}
}

} // namespace haptics::bench
