// What a player's process gets for the servo thread: runs the engine's servo at 1 kHz on the
// simulated device as whoever runs this program (tools/rt/test-rtkit.sh runs it as an
// unprivileged user, with and without RealtimeKit), then prints what the servo's stats say it
// was granted and what the kernel says the thread runs at (/proc/self/task/<tid>/stat), one
// "RTPROBE key=value ..." line each, for the script to check; and the CPU wake-up latency
// hold: the kernel's target read back from /dev/cpu_dma_latency (the least of all requests:
// docs/realtime.md) and whether this process has the file open, before the servo starts, while
// it runs and after it stopped. Exit status 0 when the servo thread was found, 1 otherwise.

#include "core/servo/servo_loop.h"
#include "system/haptics_system.h"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct KernelView {
	bool found = false;
	int policy = -1;
	long rt_priority = 0;
	long nice = 0;
};

const char *policy_name(int p_policy) {
	switch (p_policy) {
		case SCHED_OTHER:
			return "SCHED_OTHER";
		case SCHED_FIFO:
			return "SCHED_FIFO";
		case SCHED_RR:
			return "SCHED_RR";
		case SCHED_BATCH:
			return "SCHED_BATCH";
		case SCHED_IDLE:
			return "SCHED_IDLE";
		default:
			return "unknown";
	}
}

// The servo thread by its name; from its stat line: nice (field 19), rt_priority (40) and
// policy (41), counted after the parenthesised name, which may hold spaces.
KernelView servo_thread_in_proc() {
	KernelView view;
	std::error_code error;
	for (const auto &task : std::filesystem::directory_iterator("/proc/self/task", error)) {
		std::ifstream comm(task.path() / "comm");
		std::string name;
		if (!std::getline(comm, name) || name != haptics::SERVO_THREAD_NAME) {
			continue;
		}
		std::ifstream stat(task.path() / "stat");
		std::string line;
		std::getline(stat, line);
		const size_t end_of_name = line.rfind(')');
		if (end_of_name == std::string::npos) {
			continue;
		}
		std::istringstream fields(line.substr(end_of_name + 2));
		std::vector<std::string> rest; // Field 3 onwards.
		for (std::string field; fields >> field;) {
			rest.push_back(field);
		}
		if (rest.size() < 39) {
			continue;
		}
		view.found = true;
		view.nice = std::stol(rest[19 - 3]);
		view.rt_priority = std::stol(rest[40 - 3]);
		view.policy = std::stoi(rest[41 - 3]);
	}
	return view;
}

constexpr const char *LATENCY_FILE = "/dev/cpu_dma_latency";

// The kernel's CPU latency target in us (a 32-bit value read from the file); -1 when this user
// may not read it. Opening the file adds a request at the default, which changes nothing.
long long latency_target_us() {
	const int fd = ::open(LATENCY_FILE, O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		return -1;
	}
	int32_t value = 0;
	const bool read_all = ::read(fd, &value, sizeof(value)) == static_cast<ssize_t>(sizeof(value));
	::close(fd);
	return read_all ? value : -1;
}

// Whether this process has the latency file open (the kernel's record of its request).
bool holds_latency_file() {
	std::error_code error;
	for (const auto &fd : std::filesystem::directory_iterator("/proc/self/fd", error)) {
		std::error_code ignored;
		if (std::filesystem::read_symlink(fd.path(), ignored) == LATENCY_FILE) {
			return true;
		}
	}
	return false;
}

} // namespace

int main() {
	const long long target_before = latency_target_us();
	haptics::HapticsSystem system;
	const haptics::Status opened = system.open_simulated_device();
	const haptics::Status started = opened ? system.start(1000.0) : opened;
	if (!started) {
		std::printf("RTPROBE error=\"%s\"\n", started.message());
		return 1;
	}
	// The servo thread asks for its scheduling before its first tick; the stats carry it once
	// it has.
	std::this_thread::sleep_for(std::chrono::milliseconds(300));
	const haptics::ServoStats stats = system.stats();
	const KernelView kernel = servo_thread_in_proc();
	const bool file_open_running = holds_latency_file();
	const long long target_running = latency_target_us();
	std::printf("RTPROBE uid=%u euid=%u\n", ::getuid(), ::geteuid());
	std::printf("RTPROBE stats scheduler=%s priority=%d realtime_kit=\"%s\" rtkit_max=%d rttime_usec=%lld nice=%d "
				"spin_us=%lld unheld_spin_us=%lld held_spin_us=%lld reason=\"%s\"\n",
			haptics::scheduler_kind_name(stats.scheduler), stats.realtime_priority,
			haptics::rtkit_outcome_name(stats.realtime_kit.outcome), stats.realtime_kit.max_priority,
			static_cast<long long>(stats.realtime_kit.rttime_usec), stats.realtime_kit.nice,
			std::llround(stats.spin_s * 1e6), static_cast<long long>(haptics::ServoOptions::UNHELD_SPIN_NS / 1000),
			static_cast<long long>(haptics::ServoOptions::DEFAULT_SPIN_NS / 1000),
			stats.realtime_kit.reason.c_str());
	std::printf("RTPROBE kernel found=%d policy=%s rt_priority=%ld nice=%ld\n", kernel.found ? 1 : 0,
			policy_name(kernel.policy), kernel.rt_priority, kernel.nice);
	std::fflush(stdout);
	system.stop();
	std::printf("RTPROBE latency held=%d spin_learned=%d before_us=%lld running_open=%d running_us=%lld "
				"stopped_open=%d stopped_us=%lld\n",
			stats.cpu_latency_held ? 1 : 0, stats.spin_learned ? 1 : 0, target_before, file_open_running ? 1 : 0,
			target_running, holds_latency_file() ? 1 : 0, latency_target_us());
	return kernel.found ? 0 : 1;
}
