#include "core/realtime.h"

#include <algorithm>
#include <cerrno>
#include <ctime>

#include <pthread.h>
#include <sched.h>

namespace haptics {

namespace {

constexpr int64_t NS_PER_S = 1'000'000'000;

timespec to_timespec(int64_t p_ns) {
	timespec ts;
	ts.tv_sec = static_cast<time_t>(p_ns / NS_PER_S);
	ts.tv_nsec = static_cast<long>(p_ns % NS_PER_S);
	return ts;
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

} // namespace haptics
