// The servo thread's real-time techniques (realtime.h): each one granted where the process
// may have it, and each one refused quietly where it may not. The refused paths run for real
// in a child process that first gives up its privileges (a finite RLIMIT_MEMLOCK, RLIMIT_RTPRIO
// 0, and as root the switch to user nobody, which drops every capability), so they are tested
// on any machine, root or not. No timed assertion.

#include "core/base/realtime.h"
#include "system/haptics_system.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace haptics;

namespace {

// Waits (bounded: a loaded machine) until the servo has ticked p_ticks times.
void wait_for_ticks(const HapticsSystem &p_system, uint64_t p_ticks) {
	const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
	while (p_system.stats().ticks < p_ticks && std::chrono::steady_clock::now() < give_up) {
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
}

RealtimeRequest everything() {
	RealtimeRequest request;
	request.priority = 80;
	request.lock_memory = true;
	request.hold_cpu_latency = true;
	request.cpu = PIN_AUTO;
	request.prefault_stack_kb = 256;
	request.minimise_timer_slack = true;
	return request;
}

// Runs p_body on a fresh thread (the techniques apply to the calling thread).
template <typename Body>
void on_thread(Body p_body) {
	std::thread thread(p_body);
	thread.join();
}

// VmLck of this process in KiB (/proc/self/status), -1 when unknown.
long locked_kib() {
	std::ifstream status("/proc/self/status");
	std::string line;
	while (std::getline(status, line)) {
		long kib = 0;
		if (std::sscanf(line.c_str(), "VmLck: %ld kB", &kib) == 1) {
			return kib;
		}
	}
	return -1;
}

// The PM QoS CPU latency target now in force (/dev/cpu_dma_latency reads as 4 bytes), -1
// when it cannot be read.
long cpu_latency_target_us() {
	const int fd = ::open("/dev/cpu_dma_latency", O_RDONLY | O_CLOEXEC);
	if (fd < 0) {
		return -1;
	}
	int32_t value = -1;
	const ssize_t got = ::read(fd, &value, sizeof(value));
	::close(fd);
	return got == static_cast<ssize_t>(sizeof(value)) ? value : -1;
}

// What the unprivileged child saw, sent back through a pipe.
struct RefusedReport {
	bool dropped = false; // The child did give up its privileges.
	RealtimeGrants direct; // apply_realtime_request(everything()) on a thread.
	int32_t pin_out_of_range = 0; // try_pin_current_thread(100000)
	int32_t pin_auto = 0;
	ServoStats servo; // A servo run with the defaults.
	uint64_t servo_ticks = 0;
};

// Forks; the child drops its privileges, runs the techniques and a servo, reports, exits.
RefusedReport run_unprivileged() {
	int fds[2];
	REQUIRE(::pipe(fds) == 0);
	const pid_t child = ::fork();
	REQUIRE(child >= 0);
	if (child == 0) {
		::close(fds[0]);
		RefusedReport report;
		const rlimit memlock{ 64 * 1024, 64 * 1024 };
		const rlimit rtprio{ 0, 0 };
		report.dropped = ::setrlimit(RLIMIT_MEMLOCK, &memlock) == 0 && ::setrlimit(RLIMIT_RTPRIO, &rtprio) == 0;
		if (::geteuid() == 0) {
			report.dropped = report.dropped && ::setgid(65534) == 0 && ::setuid(65534) == 0;
		}
		on_thread([&] {
			report.direct = apply_realtime_request(everything());
			release_realtime_grants(report.direct);
			report.pin_out_of_range = try_pin_current_thread(100000);
			report.pin_auto = try_pin_current_thread(PIN_AUTO);
		});
		HapticsSystem system;
		if (system.open_simulated_device() && system.start(1000.0)) {
			wait_for_ticks(system, 50);
			system.stop();
			report.servo = system.stats();
			report.servo_ticks = report.servo.ticks;
		}
		const ssize_t written = ::write(fds[1], &report, sizeof(report));
		::_exit(written == static_cast<ssize_t>(sizeof(report)) ? 0 : 1);
	}
	::close(fds[1]);
	RefusedReport report;
	size_t received = 0;
	while (received < sizeof(report)) {
		const ssize_t got = ::read(fds[0], reinterpret_cast<char *>(&report) + received, sizeof(report) - received);
		if (got <= 0) {
			break;
		}
		received += static_cast<size_t>(got);
	}
	::close(fds[0]);
	int status = 0;
	REQUIRE(::waitpid(child, &status, 0) == child);
	REQUIRE(WIFEXITED(status));
	REQUIRE(WEXITSTATUS(status) == 0);
	REQUIRE(received == sizeof(report));
	return report;
}

} // namespace

TEST_CASE("realtime: without privileges every technique is refused quietly and the servo still runs") {
	const RefusedReport report = run_unprivileged();
	REQUIRE(report.dropped);
	CHECK(report.direct.kind == SchedulerKind::NORMAL);
	CHECK(report.direct.priority == 0);
	CHECK_FALSE(report.direct.memory_locked);
	CHECK_FALSE(report.direct.cpu_latency_held);
	CHECK(report.direct.timer_slack_minimised); // The fallback for SCHED_OTHER is allowed.
	CHECK(report.direct.cpu >= 0); // Pinning needs no privilege.
	CHECK(report.direct.stack_prefaulted_kb == 256);
	CHECK(report.pin_out_of_range == -1);
	CHECK(report.pin_auto >= 0);

	CHECK(report.servo_ticks >= 50);
	CHECK(report.servo.scheduler == SchedulerKind::NORMAL);
	CHECK_FALSE(report.servo.memory_locked);
	CHECK_FALSE(report.servo.cpu_latency_held);
	CHECK(report.servo.timer_slack_minimised);
}

TEST_CASE("realtime: where the process may have them, the techniques are granted and released") {
	const bool may_lock = [] {
		rlimit limit{};
		return ::geteuid() == 0 || (::getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY);
	}();
	const bool may_hold_latency = ::access("/dev/cpu_dma_latency", W_OK) == 0;
	const bool may_fifo = [] {
		rlimit limit{};
		return ::geteuid() == 0 || (::getrlimit(RLIMIT_RTPRIO, &limit) == 0 && limit.rlim_cur >= 80);
	}();
	MESSAGE("may lock memory: " << may_lock << ", may hold the CPU latency: " << may_hold_latency
								<< ", may use SCHED_FIFO 80: " << may_fifo);
	const long latency_before = cpu_latency_target_us();
	on_thread([&] {
		const RealtimeGrants grants = apply_realtime_request(everything());
		CHECK(grants.memory_locked == may_lock);
		CHECK(grants.cpu_latency_held == may_hold_latency);
		CHECK((grants.kind == SchedulerKind::REALTIME_FIFO) == may_fifo);
		CHECK(grants.timer_slack_minimised == (grants.kind == SchedulerKind::NORMAL)); // Only tried without real time.
		CHECK(grants.stack_prefaulted_kb == 256);
		REQUIRE(grants.cpu >= 0);
		CHECK(::sched_getcpu() == grants.cpu);
		if (may_lock) {
			CHECK(locked_kib() > 0);
		}
		if (may_hold_latency) {
			CHECK(cpu_latency_target_us() == 0);
		}
		release_realtime_grants(grants);
	});
	if (may_lock) {
		CHECK(locked_kib() == 0);
	}
	if (may_hold_latency) {
		CHECK(cpu_latency_target_us() == latency_before);
	}
}

TEST_CASE("realtime: the process-wide holds are counted, released by the last holder") {
	if (!acquire_memory_lock()) {
		MESSAGE("memory locking not permitted here; the refused path is the test above");
		return;
	}
	CHECK(acquire_memory_lock());
	release_memory_lock();
	CHECK(locked_kib() > 0); // One holder left.
	release_memory_lock();
	CHECK(locked_kib() == 0);
	release_memory_lock(); // An extra release is harmless.
	CHECK(locked_kib() == 0);
}

TEST_CASE("realtime: nothing asked, nothing taken") {
	on_thread([] {
		RealtimeRequest none;
		none.priority = 0;
		none.lock_memory = false;
		none.hold_cpu_latency = false;
		none.cpu = PIN_NONE;
		none.prefault_stack_kb = 0;
		none.minimise_timer_slack = false;
		const RealtimeGrants grants = apply_realtime_request(none);
		CHECK(grants.kind == SchedulerKind::NORMAL);
		CHECK_FALSE(grants.memory_locked);
		CHECK_FALSE(grants.cpu_latency_held);
		CHECK(grants.cpu == -1);
		CHECK(grants.stack_prefaulted_kb == 0);
		CHECK_FALSE(grants.timer_slack_minimised);
		release_realtime_grants(grants);
	});
}

TEST_CASE("realtime: the stack prefault stays inside a small stack") {
	pthread_attr_t attributes;
	REQUIRE(pthread_attr_init(&attributes) == 0);
	REQUIRE(pthread_attr_setstacksize(&attributes, 256 * 1024) == 0);
	int32_t touched = -1;
	pthread_t thread;
	REQUIRE(pthread_create(
					&thread, &attributes,
					[](void *p_out) -> void * {
						*static_cast<int32_t *>(p_out) = prefault_current_stack(4096); // 4 MiB asked.
						return nullptr;
					},
					&touched) == 0);
	pthread_join(thread, nullptr);
	pthread_attr_destroy(&attributes);
	CHECK(touched > 0);
	CHECK(touched < 256);
}

TEST_CASE("realtime: the spin never returns before the deadline") {
	for (int i = 0; i < 20; ++i) {
		const int64_t deadline = monotonic_now_ns() + 300'000;
		sleep_then_spin_until_ns(deadline, 100'000);
		CHECK(monotonic_now_ns() >= deadline);
	}
	const int64_t past = monotonic_now_ns() - 1'000'000;
	sleep_then_spin_until_ns(past, 100'000); // Returns at once.
}

TEST_CASE("servo thread: spin and techniques show in the stats, a spin over half a period is refused") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	ServoOptions options;
	options.spin_ns = 600'000;
	CHECK(system.start(options).code() == StatusCode::INVALID_ARGUMENT);
	options.spin_ns = -2; // -1 is SPIN_AUTO.
	CHECK(system.start(options).code() == StatusCode::INVALID_ARGUMENT);
	options.spin_ns = 50'000;
	options.realtime.cpu = PIN_AUTO;
	REQUIRE(system.start(options));
	wait_for_ticks(system, 1500);
	const ServoStats running = system.stats();
	system.stop();
	CHECK(running.ticks >= 1500);
	CHECK(running.spin_s == doctest::Approx(50e-6));
	CHECK(running.pinned_cpu >= 0);
	CHECK(running.stack_prefaulted_kb == options.realtime.prefault_stack_kb);
	// Spinning 50 us of every 1 000 us costs CPU; a thread that only slept would use ~0.
	CHECK(running.thread_cpu_fraction > 0.01);
	CHECK(running.thread_cpu_fraction <= 1.0);
	CHECK(running.latency_max_s >= running.latency_p99_s);
	CHECK(running.latency_p99_s >= running.latency_p50_s);
	const ServoStats stopped = system.stats();
	CHECK(stopped.pinned_cpu == running.pinned_cpu); // Still says what the run had.
}

TEST_CASE("servo thread: a spin of exactly half a period is accepted, a nanosecond more is refused") {
	CHECK(max_spin_ns(1000.0) == 500'000);
	CHECK(max_spin_ns(3000.0) == 166'666); // Half the period the loop rounds to (333 333 ns).
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	ServoOptions options;
	options.rate_hz = 4000.0;
	options.spin_ns = max_spin_ns(options.rate_hz) + 1;
	CHECK(system.start(options).code() == StatusCode::INVALID_ARGUMENT);
	CHECK_FALSE(system.is_running());
	options.spin_ns = max_spin_ns(options.rate_hz);
	REQUIRE(system.start(options));
	system.stop();
	CHECK(system.stats().spin_s == doctest::Approx(125e-6));
}

TEST_CASE("servo thread: the automatic spin follows what the thread was granted") {
	ServoOptions options;
	REQUIRE(options.spin_ns == ServoOptions::SPIN_AUTO);
	RealtimeGrants root; // SCHED_FIFO with the CPU latency held.
	root.kind = SchedulerKind::REALTIME_FIFO;
	root.cpu_latency_held = true;
	RealtimeGrants user; // RealtimeKit's SCHED_RR; the latency file is root's.
	user.kind = SchedulerKind::REALTIME_RR;
	const RealtimeGrants normal;
	CHECK(effective_spin_ns(options, root) == ServoOptions::DEFAULT_SPIN_NS);
	CHECK(effective_spin_ns(options, user) == ServoOptions::UNHELD_SPIN_NS);
	CHECK(effective_spin_ns(options, normal) == 0);
	// Only the user's real time without the hold learns its spin (wake_ahead.h), from there.
	CHECK(learns_spin(options, user));
	CHECK_FALSE(learns_spin(options, root));
	CHECK_FALSE(learns_spin(options, normal));
	options.rate_hz = 4000.0; // Never more than half a period (125 us).
	CHECK(effective_spin_ns(options, user) == std::min(ServoOptions::UNHELD_SPIN_NS, max_spin_ns(4000.0)));
	options.rate_hz = 1000.0;
	options.spin_ns = 120'000; // Asked for: kept, real time or not.
	CHECK(effective_spin_ns(options, normal) == 120'000);
	CHECK(effective_spin_ns(options, user) == 120'000);
	CHECK_FALSE(learns_spin(options, user)); // A spin asked for is not learned.
	options.scheduling = LoopScheduling::NAIVE_SLEEP;
	CHECK(effective_spin_ns(options, root) == 0);

	// A thread that is not real-time (nothing asked) reports no spin.
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	ServoOptions unprivileged;
	unprivileged.realtime.priority = 0;
	unprivileged.realtime.hold_cpu_latency = false;
	REQUIRE(system.start(unprivileged));
	wait_for_ticks(system, 10);
	const ServoStats stats = system.stats();
	system.stop();
	CHECK(stats.scheduler == SchedulerKind::NORMAL);
	CHECK(stats.spin_s == 0.0);
}

TEST_CASE("servo thread: with real time but no latency hold it learns its spin, within its bounds") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	ServoOptions options;
	options.realtime.priority = 20; // As RealtimeKit grants a user.
	options.realtime.hold_cpu_latency = false;
	REQUIRE(system.start(options));
	wait_for_ticks(system, 10);
	const ServoStats stats = system.stats();
	system.stop();
	if (!stats.realtime) {
		MESSAGE("no real time here: the learning is tested against a scripted clock (test_wake_ahead.cpp)");
		CHECK_FALSE(stats.spin_learned);
		return;
	}
	CHECK(stats.spin_learned);
	CHECK_FALSE(stats.cpu_latency_held);
	CHECK(stats.spin_s >= static_cast<double>(WAKE_AHEAD_MIN_NS) * 1e-9);
	CHECK(stats.spin_s <= static_cast<double>(WAKE_AHEAD_MAX_NS) * 1e-9);
}
