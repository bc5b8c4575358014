#include "core/base/realtime.h"
#include "core/base/realtime_shared.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <mutex>

#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

namespace haptics {

namespace {

constexpr int64_t NS_PER_S = 1'000'000'000;
constexpr int CAP_IPC_LOCK_BIT = 14; // linux/capability.h

timespec to_timespec(int64_t p_ns) {
	timespec ts;
	ts.tv_sec = static_cast<time_t>(p_ns / NS_PER_S);
	ts.tv_nsec = static_cast<long>(p_ns % NS_PER_S);
	return ts;
}

// Whether capability p_bit is in the process's effective set (/proc/self/status, CapEff).
bool has_effective_capability(int p_bit) {
	FILE *status = std::fopen("/proc/self/status", "re");
	if (!status) {
		return false;
	}
	char line[256];
	unsigned long long mask = 0;
	bool found = false;
	while (std::fgets(line, sizeof(line), status)) {
		if (std::sscanf(line, "CapEff: %llx", &mask) == 1) {
			found = true;
			break;
		}
	}
	std::fclose(status);
	return found && (mask >> p_bit) & 1ULL;
}

// The process-wide holds, counted; taken and released at servo start and stop only.
struct ProcessHolds {
	std::mutex mutex;
	int memory_lock_count = 0;
	int latency_count = 0;
	int latency_fd = -1;
};

ProcessHolds &process_holds() {
	static ProcessHolds holds;
	return holds;
}

} // namespace

int64_t monotonic_now_ns() {
	timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return static_cast<int64_t>(ts.tv_sec) * NS_PER_S + ts.tv_nsec;
}

void sleep_until_ns(int64_t p_deadline_ns) {
	const timespec deadline = to_timespec(p_deadline_ns);
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
	}
}

void sleep_for_ns(int64_t p_duration_ns) {
	timespec remaining = to_timespec(std::max<int64_t>(0, p_duration_ns));
	while (nanosleep(&remaining, &remaining) == -1 && errno == EINTR) {
	}
}

int64_t thread_cpu_time_ns() {
	timespec ts;
	if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) {
		return 0;
	}
	return static_cast<int64_t>(ts.tv_sec) * NS_PER_S + ts.tv_nsec;
}

void set_current_thread_name(const char *p_name) {
	::pthread_setname_np(::pthread_self(), p_name);
}

RealtimeResult try_make_current_thread_realtime(int32_t p_priority) {
	RealtimeResult result;
	if (p_priority <= 0) {
		return result;
	}
	const int min_priority = sched_get_priority_min(SCHED_FIFO);
	const int max_priority = sched_get_priority_max(SCHED_FIFO);
	sched_param param{};
	param.sched_priority = std::clamp(static_cast<int>(p_priority), min_priority, max_priority);
	if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0) {
		result.kind = SchedulerKind::REALTIME_FIFO;
		result.priority = param.sched_priority;
	}
	return result;
}

int32_t try_pin_current_thread(int32_t p_cpu) {
	if (p_cpu == PIN_NONE || (p_cpu < 0 && p_cpu != PIN_AUTO) || p_cpu >= CPU_SETSIZE) {
		return -1;
	}
	cpu_set_t allowed;
	CPU_ZERO(&allowed);
	if (pthread_getaffinity_np(pthread_self(), sizeof(allowed), &allowed) != 0) {
		return -1;
	}
	int cpu = p_cpu;
	if (p_cpu == PIN_AUTO) {
		cpu = -1;
		for (int c = CPU_SETSIZE - 1; c >= 0; --c) {
			if (CPU_ISSET(c, &allowed)) {
				cpu = c;
				break;
			}
		}
	}
	if (cpu < 0 || !CPU_ISSET(cpu, &allowed)) {
		return -1;
	}
	cpu_set_t one;
	CPU_ZERO(&one);
	CPU_SET(cpu, &one);
	return pthread_setaffinity_np(pthread_self(), sizeof(one), &one) == 0 ? cpu : -1;
}

int32_t prefault_current_stack(int32_t p_kb) {
	if (p_kb <= 0) {
		return 0;
	}
	pthread_attr_t attributes;
	if (pthread_getattr_np(pthread_self(), &attributes) != 0) {
		return 0;
	}
	void *stack_low = nullptr;
	size_t stack_size = 0;
	const bool known = pthread_attr_getstack(&attributes, &stack_low, &stack_size) == 0;
	pthread_attr_destroy(&attributes);
	if (!known) {
		return 0;
	}
	return prefault_stack_above(reinterpret_cast<uintptr_t>(stack_low), p_kb);
}

bool minimise_current_timer_slack() {
	return prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL) == 0;
}

bool acquire_memory_lock() {
	ProcessHolds &holds = process_holds();
	const std::lock_guard<std::mutex> lock(holds.mutex);
	if (holds.memory_lock_count > 0) {
		++holds.memory_lock_count;
		return true;
	}
	rlimit limit{};
	const bool unlimited = getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
	if (!unlimited && !has_effective_capability(CAP_IPC_LOCK_BIT)) {
		return false;
	}
	if (mlockall(MCL_CURRENT | MCL_FUTURE | MCL_ONFAULT) != 0) {
		return false;
	}
	holds.memory_lock_count = 1;
	return true;
}

void release_memory_lock() {
	ProcessHolds &holds = process_holds();
	const std::lock_guard<std::mutex> lock(holds.mutex);
	if (holds.memory_lock_count > 0 && --holds.memory_lock_count == 0) {
		munlockall();
	}
}

bool acquire_cpu_latency_hold() {
	ProcessHolds &holds = process_holds();
	const std::lock_guard<std::mutex> lock(holds.mutex);
	if (holds.latency_count > 0) {
		++holds.latency_count;
		return true;
	}
	const int fd = open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
	if (fd < 0) {
		return false;
	}
	const int32_t zero_us = 0;
	if (write(fd, &zero_us, sizeof(zero_us)) != static_cast<ssize_t>(sizeof(zero_us))) {
		close(fd);
		return false;
	}
	holds.latency_fd = fd; // The request holds while the file stays open.
	holds.latency_count = 1;
	return true;
}

void release_cpu_latency_hold() {
	ProcessHolds &holds = process_holds();
	const std::lock_guard<std::mutex> lock(holds.mutex);
	if (holds.latency_count > 0 && --holds.latency_count == 0) {
		close(holds.latency_fd);
		holds.latency_fd = -1;
	}
}

RealtimeGrants apply_realtime_request(const RealtimeRequest &p_request) {
	RealtimeGrants grants;
	grants.memory_locked = p_request.lock_memory && acquire_memory_lock();
	grants.cpu_latency_held = p_request.hold_cpu_latency && acquire_cpu_latency_hold();
	const RealtimeResult scheduler = try_make_current_thread_realtime(p_request.priority);
	grants.kind = scheduler.kind;
	grants.priority = scheduler.priority;
	if (grants.kind == SchedulerKind::NORMAL && p_request.priority > 0 && p_request.ask_realtime_kit) {
		grants.realtime_kit = request_realtime_from_rtkit(p_request.priority);
		if (grants.realtime_kit.outcome == RtkitOutcome::REALTIME) {
			grants.kind = SchedulerKind::REALTIME_RR;
			grants.priority = grants.realtime_kit.priority;
		}
	}
	if (p_request.minimise_timer_slack && grants.kind == SchedulerKind::NORMAL) {
		grants.timer_slack_minimised = minimise_current_timer_slack();
	}
	grants.cpu = try_pin_current_thread(p_request.cpu);
	grants.stack_prefaulted_kb = prefault_current_stack(p_request.prefault_stack_kb);
	return grants;
}

void release_realtime_grants(const RealtimeGrants &p_grants) {
	if (p_grants.memory_locked) {
		release_memory_lock();
	}
	if (p_grants.cpu_latency_held) {
		release_cpu_latency_hold();
	}
}

} // namespace haptics
