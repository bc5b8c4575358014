#pragma once

// Inside the fake OpenHaptics runtime: its own restatement of the HD types and values it
// serves (docs/devices/openhaptics.md, "Types" and "Constants"), written apart from the backend's hd_api.h on purpose, so a
// wrong width or value on either side shows up as a failing test instead of cancelling out.

#include "fake_hd_control.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#define FAKE_HD_EXPORT extern "C" __attribute__((visibility("default")))

namespace fake_hd {

struct ErrorInfo { // HDErrorInfo: {HDerror, int, HHD}, 12 bytes, returned by value.
	unsigned int errorCode;
	int internalErrorCode;
	unsigned int hHD;
};
static_assert(sizeof(ErrorInfo) == 12);

using Callback = unsigned int (*)(void *); // HDSchedulerCallback (stdcall is a no-op on x86-64)

constexpr unsigned int INVALID_HANDLE = 0xFFFFFFFFu;
constexpr unsigned int DEVICE_HANDLE = 0; // HD's first device handle.
constexpr unsigned int CALLBACK_DONE = 0;

constexpr unsigned int SUCCESS = 0x0000;
constexpr unsigned int EXCEEDED_MAX_FORCE = 0x0201;
constexpr unsigned int DEVICE_ALREADY_INITIATED = 0x0301;
constexpr unsigned int COMM_ERROR = 0x0302;

constexpr unsigned int CURRENT_POSITION = 0x2050;
constexpr unsigned int CURRENT_VELOCITY = 0x2051;
constexpr unsigned int CURRENT_TRANSFORM = 0x2052;
constexpr unsigned int CURRENT_BUTTONS = 0x2000;
constexpr unsigned int CURRENT_FORCE = 0x2700;
constexpr unsigned int NOMINAL_MAX_FORCE = 0x2603;

constexpr unsigned int CALIBRATION_OK = 0x5000;
constexpr unsigned int CALIBRATION_NEEDS_UPDATE = 0x5001;

// Parameters only valid inside a frame: current/last state (0x2000-0x22FF) and forces and
// torques (0x2700-0x28FF).
inline bool is_frame_parameter(unsigned int p_pname) {
	return (p_pname >= 0x2000 && p_pname < 0x2300) || (p_pname >= 0x2700 && p_pname < 0x2900);
}

struct Scheduled {
	unsigned long handle;
	Callback function;
	void *data;
	unsigned short priority;
	bool synchronous;
	uint64_t order; // Scheduling order among equal priorities.
};

struct Parameter {
	unsigned int pname;
	int count;
	double values[16];
};

// The whole fake device and scheduler. One instance (state()); every member below the
// mutex is guarded by it, except what is atomic.
struct State {
	std::mutex mutex;
	// Script.
	std::vector<Parameter> doubles;
	std::vector<Parameter> integers;
	std::vector<std::pair<unsigned int, std::string>> strings;
	std::vector<unsigned int> null_strings;
	unsigned int calibration = CALIBRATION_OK;
	ErrorInfo init_failure{};
	bool unplugged = false;
	std::vector<ErrorInfo> injected; // Pushed at the next hdEndFrame.
	std::vector<ErrorInfo> errors; // The error stack.
	// Device.
	bool initiated = false;
	unsigned int current = INVALID_HANDLE;
	// Scheduler.
	std::vector<Scheduled> scheduled;
	std::vector<unsigned long> finished; // Synchronous callbacks that returned DONE.
	unsigned long next_handle = 1;
	uint64_t next_order = 0;
	unsigned long rate_hz = 1000;
	std::atomic<bool> free_running{ false };
	std::thread thread;
	std::atomic<bool> running{ false };
	std::atomic<bool> stop_requested{ false };
	std::condition_variable changed; // A sync callback finished, or a tick ran.
	std::atomic<uint64_t> ticks{ 0 };
	// Record.
	std::atomic<bool> recording{ true };
	std::vector<FakeHdCall> calls;
	uint64_t misuse = 0;
	std::string misuse_text;
	uint64_t force_sets = 0;
	double last_force[3] = {};
	std::vector<double> callback_ns; // Ring of the latest async callback durations.
	size_t callback_next = 0;
	size_t callback_filled = 0;

	State(); // The defaults of fake_hd_reset().
	~State();
};

State &state();

// Per thread: frame depth, whether this is the scheduler, the callback it runs.
struct ThreadContext {
	int frame_depth = 0;
	bool scheduler = false;
	unsigned long callback = 0;
};
ThreadContext &thread_context();

// Appends a call (when recording); the caller holds the mutex. p_values may be null when
// p_count is 0.
void record(State &r_state, const char *p_name, unsigned int p_pname, const double *p_values, int p_count);
void note_misuse(State &r_state, const std::string &p_text); // Caller holds the mutex.

void start_scheduler(State &r_state); // Caller holds no lock.
void stop_scheduler(State &r_state); // Joins; caller holds no lock.

} // namespace fake_hd
