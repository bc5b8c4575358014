// The servo thread's timing primitives on Windows (realtime_windows.cpp): what they report is
// what the thread got, and no sleep ends before its deadline.
#include <doctest/doctest.h>

#include "core/base/realtime.h"

#include <windows.h>

#include <string>
#include <thread>

using namespace haptics;

TEST_CASE("realtime (Windows): the thread gets an MMCSS task or stays normal, at time-critical priority") {
	RealtimeGrants grants;
	int thread_priority = 0;
	std::thread servo([&] {
		grants = apply_realtime_request(RealtimeRequest{});
		thread_priority = GetThreadPriority(GetCurrentThread());
	});
	servo.join();
	MESSAGE("scheduler: " << std::string(scheduler_kind_name(grants.kind)) << ", priority " << grants.priority
						  << ", high-resolution timer " << grants.timer_slack_minimised);
	CHECK((grants.kind == SchedulerKind::MMCSS_PRO_AUDIO || grants.kind == SchedulerKind::MMCSS_GAMES ||
			grants.kind == SchedulerKind::NORMAL));
	CHECK(grants.priority == THREAD_PRIORITY_TIME_CRITICAL);
	CHECK(thread_priority == THREAD_PRIORITY_TIME_CRITICAL);
	// No counterpart a normal user can take on Windows: never claimed.
	CHECK_FALSE(grants.memory_locked);
	CHECK_FALSE(grants.cpu_latency_held);
}

TEST_CASE("realtime (Windows): nothing asked, the thread keeps its priority") {
	RealtimeRequest request;
	request.priority = 0;
	RealtimeGrants grants;
	int thread_priority = -100;
	std::thread servo([&] {
		grants = apply_realtime_request(request);
		thread_priority = GetThreadPriority(GetCurrentThread());
	});
	servo.join();
	CHECK(grants.kind == SchedulerKind::NORMAL);
	CHECK(grants.priority == 0);
	CHECK(thread_priority == THREAD_PRIORITY_NORMAL);
}

TEST_CASE("realtime (Windows): sleeps never end before their deadline, the spin neither") {
	for (int64_t period_ns : { 100'000, 1'000'000, 2'500'000 }) {
		for (int i = 0; i < 20; ++i) {
			const int64_t deadline = monotonic_now_ns() + period_ns;
			sleep_until_ns(deadline);
			REQUIRE(monotonic_now_ns() >= deadline);
			const int64_t spun = monotonic_now_ns() + period_ns;
			sleep_then_spin_until_ns(spun, period_ns / 2);
			REQUIRE(monotonic_now_ns() >= spun);
		}
	}
	const int64_t before = thread_cpu_time_ns();
	const int64_t busy_until = monotonic_now_ns() + 50'000'000;
	while (monotonic_now_ns() < busy_until) {
	}
	CHECK(thread_cpu_time_ns() > before);
}

TEST_CASE("realtime (Windows): pinning takes an allowed CPU and refuses others") {
	int32_t pinned = -2;
	int32_t refused = -2;
	std::thread servo([&] {
		pinned = try_pin_current_thread(PIN_AUTO);
		refused = try_pin_current_thread(63);
	});
	servo.join();
	CHECK(pinned >= 0);
	CHECK(pinned < static_cast<int32_t>(std::thread::hardware_concurrency()));
	CHECK((refused == -1 || std::thread::hardware_concurrency() == 64));
	CHECK(try_pin_current_thread(PIN_NONE) == -1);
}
