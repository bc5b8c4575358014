#include "core/base/realtime.h"
#include "core/base/realtime_shared.h"

#include <algorithm>

#include <windows.h>
// After windows.h, which it needs.
#include <avrt.h>

// Windows 10 1803's flag (synchapi.h of newer SDKs); older Windows refuse it, and the timer
// falls back to the default resolution.
#ifndef CREATE_WAITABLE_TIMER_HIGH_RESOLUTION
#define CREATE_WAITABLE_TIMER_HIGH_RESOLUTION 0x00000002
#endif

// What Windows gives a normal user's thread, reported through the Linux techniques' fields:
//   - the scheduler: the multimedia class scheduler's "Pro Audio" task (else "Games"), which
//     lifts the thread into the real-time priority range while it is registered, plus
//     THREAD_PRIORITY_TIME_CRITICAL; kind MMCSS_*, priority the thread's priority;
//   - timer_slack_minimised: the sleep uses a high-resolution waitable timer (Windows 10
//     1803+), which wakes within well under a millisecond without timeBeginPeriod; a plain
//     waitable timer ends on the system's 15.6 ms tick unless someone raised it;
//   - pinning and the stack prefault as on Linux;
//   - memory locking and the CPU latency hold have no counterpart a normal user can take
//     (VirtualLock is bounded by the working set, power policy needs an administrator): never
//     granted here, so memory_locked and cpu_latency_held stay false.

namespace haptics {

namespace {

constexpr int64_t NS_PER_S = 1'000'000'000;
constexpr int64_t NS_PER_FILETIME_UNIT = 100;

int64_t counter_frequency() {
	static const int64_t frequency = [] {
		LARGE_INTEGER value;
		QueryPerformanceFrequency(&value);
		return static_cast<int64_t>(value.QuadPart);
	}();
	return frequency;
}

// The calling thread's waitable timer, made once per thread (before the loop, by
// apply_realtime_request; later calls reuse it, so the tick never creates one).
struct ThreadTimer {
	HANDLE handle = nullptr;
	bool high_resolution = false;
	ThreadTimer() {
		handle = CreateWaitableTimerExW(nullptr, nullptr, CREATE_WAITABLE_TIMER_HIGH_RESOLUTION, TIMER_ALL_ACCESS);
		high_resolution = handle != nullptr;
		if (handle == nullptr) {
			handle = CreateWaitableTimerExW(nullptr, nullptr, 0, TIMER_ALL_ACCESS);
		}
	}
	ThreadTimer(const ThreadTimer &) = delete;
	ThreadTimer &operator=(const ThreadTimer &) = delete;
	~ThreadTimer() {
		if (handle != nullptr) {
			CloseHandle(handle);
		}
	}
};

ThreadTimer &thread_timer() {
	thread_local ThreadTimer timer;
	return timer;
}

// Sleeps p_ns (relative: the timer's absolute time is the wall clock, which may jump).
void sleep_relative_ns(int64_t p_ns) {
	if (p_ns <= 0) {
		return;
	}
	ThreadTimer &timer = thread_timer();
	if (timer.handle == nullptr) {
		Sleep(static_cast<DWORD>((p_ns + 999'999) / 1'000'000));
		return;
	}
	LARGE_INTEGER due;
	due.QuadPart = -std::max<int64_t>(1, p_ns / NS_PER_FILETIME_UNIT);
	if (SetWaitableTimer(timer.handle, &due, 0, nullptr, nullptr, FALSE)) {
		WaitForSingleObject(timer.handle, INFINITE);
	}
}

} // namespace

int64_t monotonic_now_ns() {
	LARGE_INTEGER counter;
	QueryPerformanceCounter(&counter);
	const int64_t frequency = counter_frequency();
	const int64_t ticks = counter.QuadPart;
	return ticks / frequency * NS_PER_S + ticks % frequency * NS_PER_S / frequency;
}

// The waitable timer is relative, so a wake-up can end early only by rounding: loop until
// the monotonic clock has passed the deadline, as clock_nanosleep's absolute sleep would.
void sleep_until_ns(int64_t p_deadline_ns) {
	for (int64_t now = monotonic_now_ns(); now < p_deadline_ns; now = monotonic_now_ns()) {
		sleep_relative_ns(p_deadline_ns - now);
	}
}

void sleep_for_ns(int64_t p_duration_ns) {
	sleep_relative_ns(p_duration_ns);
}

int64_t thread_cpu_time_ns() {
	FILETIME creation, exit, kernel, user;
	if (!GetThreadTimes(GetCurrentThread(), &creation, &exit, &kernel, &user)) {
		return 0;
	}
	const auto units = [](const FILETIME &p_time) {
		return static_cast<int64_t>((static_cast<uint64_t>(p_time.dwHighDateTime) << 32) | p_time.dwLowDateTime);
	};
	return (units(kernel) + units(user)) * NS_PER_FILETIME_UNIT;
}

void set_current_thread_name(const char *p_name) {
	// SetThreadDescription is Windows 10 1607+: looked up, so older systems still load us.
	using SetDescription = HRESULT(WINAPI *)(HANDLE, PCWSTR);
	const HMODULE kernel = GetModuleHandleW(L"kernel32.dll");
	const auto set_description = kernel == nullptr
			? nullptr
			: reinterpret_cast<SetDescription>(reinterpret_cast<void (*)()>(GetProcAddress(kernel, "SetThreadDescription")));
	if (set_description == nullptr) {
		return;
	}
	wchar_t wide[32] = {};
	for (size_t i = 0; i + 1 < sizeof(wide) / sizeof(wide[0]) && p_name[i] != '\0'; ++i) {
		wide[i] = static_cast<wchar_t>(static_cast<unsigned char>(p_name[i]));
	}
	set_description(GetCurrentThread(), wide);
}

RealtimeResult try_make_current_thread_realtime(int32_t p_priority) {
	RealtimeResult result;
	if (p_priority <= 0) {
		return result;
	}
	// The registration lasts as long as the thread: it is never reverted (the thread ends).
	DWORD task_index = 0;
	if (AvSetMmThreadCharacteristicsW(L"Pro Audio", &task_index) != nullptr) {
		result.kind = SchedulerKind::MMCSS_PRO_AUDIO;
	} else if (AvSetMmThreadCharacteristicsW(L"Games", &task_index) != nullptr) {
		result.kind = SchedulerKind::MMCSS_GAMES;
	}
	SetThreadPriority(GetCurrentThread(), THREAD_PRIORITY_TIME_CRITICAL);
	result.priority = GetThreadPriority(GetCurrentThread());
	return result;
}

int32_t try_pin_current_thread(int32_t p_cpu) {
	if (p_cpu == PIN_NONE || (p_cpu < 0 && p_cpu != PIN_AUTO) || p_cpu >= 64) {
		return -1;
	}
	DWORD_PTR process_mask = 0;
	DWORD_PTR system_mask = 0;
	if (!GetProcessAffinityMask(GetCurrentProcess(), &process_mask, &system_mask)) {
		return -1;
	}
	int cpu = p_cpu;
	if (p_cpu == PIN_AUTO) {
		cpu = process_mask == 0 ? -1 : 63 - __builtin_clzll(process_mask);
	}
	if (cpu < 0 || ((process_mask >> cpu) & 1) == 0) {
		return -1;
	}
	return SetThreadAffinityMask(GetCurrentThread(), DWORD_PTR{ 1 } << cpu) != 0 ? cpu : -1;
}

int32_t prefault_current_stack(int32_t p_kb) {
	if (p_kb <= 0) {
		return 0;
	}
	ULONG_PTR low = 0;
	ULONG_PTR high = 0;
	GetCurrentThreadStackLimits(&low, &high);
	return low == 0 ? 0 : prefault_stack_above(static_cast<uintptr_t>(low), p_kb);
}

bool minimise_current_timer_slack() {
	return thread_timer().high_resolution;
}

bool acquire_memory_lock() {
	return false;
}

void release_memory_lock() {}

bool acquire_cpu_latency_hold() {
	return false;
}

void release_cpu_latency_hold() {}

RealtimeGrants apply_realtime_request(const RealtimeRequest &p_request) {
	RealtimeGrants grants;
	const RealtimeResult scheduler = try_make_current_thread_realtime(p_request.priority);
	grants.kind = scheduler.kind;
	grants.priority = scheduler.priority;
	// The timer is made here, whatever was asked: every sleep of the loop uses it.
	grants.timer_slack_minimised = minimise_current_timer_slack();
	grants.cpu = try_pin_current_thread(p_request.cpu);
	grants.stack_prefaulted_kb = prefault_current_stack(p_request.prefault_stack_kb);
	return grants;
}

void release_realtime_grants(const RealtimeGrants &) {}

} // namespace haptics
