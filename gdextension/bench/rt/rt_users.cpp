#include "rt_users.h"

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

// A bus nobody listens on: the child's RealtimeKit is then "unavailable", as on a machine
// without a system bus.
constexpr const char *NO_BUS = "unix:path=/nonexistent/haptics-no-bus";

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

bool run_servo_child(const std::string &p_user, const std::string &p_bus, double p_seconds, ServoChildReport &r_report,
		std::string &r_error) {
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
	const std::vector<std::string> argv = { "setpriv", "--reuid=" + std::to_string(account->pw_uid),
		"--regid=" + std::to_string(account->pw_gid), "--clear-groups",
		"--inh-caps=-all", "env", "-i", "DBUS_SYSTEM_BUS_ADDRESS=" + (p_bus.empty() ? std::string(NO_BUS) : p_bus),
		"PATH=/usr/bin:/bin", self, "--servo-child", std::to_string(p_seconds) };
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
	constexpr double US = 1e6;
	const Distribution &root = p_result.servo.latency;
	bool header = false;
	for (const auto &[label, r] : p_result.techniques) {
		if (label.rfind("as ", 0) != 0 || !r.measured || !root.measured) {
			continue;
		}
		if (!header) {
			std::printf("\n  The servo as an ordinary user [%s] against root's (SCHED_%s %d) in the same rounds: wake latency "
						"p99 / p99.9 in us\n",
					p_result.name.c_str(), p_result.servo.stats.scheduler == SchedulerKind::REALTIME_FIFO ? "FIFO" : "OTHER",
					p_result.servo.stats.realtime_priority);
			std::printf("  %-34s %8.1f %8.1f\n", "root", root.p99 * US, root.p999 * US);
			header = true;
		}
		const double r99 = root.p99 > 0.0 ? r.latency.p99 / root.p99 : 0.0;
		const double r999 = root.p999 > 0.0 ? r.latency.p999 / root.p999 : 0.0;
		std::printf("  %-34s %8.1f %8.1f  x%.2f x%.2f  (%s %d, RealtimeKit: %s)\n", label.c_str(), r.latency.p99 * US,
				r.latency.p999 * US, r99, r999, scheduler_kind_name(r.stats.scheduler), r.stats.realtime_priority,
				rtkit_outcome_name(r.stats.realtime_kit.outcome));
	}
}

} // namespace haptics::bench
