// The fake runtime's state, its scheduler thread and the fake_hd_* control functions.

#include "fake_hd_state.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace fake_hd {

namespace {

constexpr size_t MAX_CALLS = 2'000'000; // About 300 MB would be a runaway test; stop there.
constexpr size_t CALLBACK_COSTS = 1 << 16;

// std::chrono's steady clock, not clock_nanosleep: the fake runs on Windows too, where
// winpthreads' clock_nanosleep does not sleep to a CLOCK_MONOTONIC deadline.
int64_t now_ns() {
	return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
			.count();
}

void sleep_until(int64_t p_deadline_ns) {
	std::this_thread::sleep_until(std::chrono::steady_clock::time_point(std::chrono::nanoseconds(p_deadline_ns)));
}

// A Touch-like default: the usable box is off-centre in y and z so that centring shows.
void set_defaults(State &r_state) {
	const auto set = [&r_state](unsigned int p_pname, std::initializer_list<double> p_values) {
		Parameter parameter{ p_pname, static_cast<int>(p_values.size()), {} };
		std::copy(p_values.begin(), p_values.end(), parameter.values);
		r_state.doubles.push_back(parameter);
	};
	r_state.doubles.clear();
	r_state.integers.clear();
	r_state.strings.clear();
	r_state.null_strings.clear();
	set(0x2551, { -80.0, -50.0, -40.0, 80.0, 70.0, 60.0 }); // HD_USABLE_WORKSPACE_DIMENSIONS: centre (0, 10, 10) mm
	set(0x2603, { 3.3 }); // HD_NOMINAL_MAX_FORCE
	set(0x2604, { 0.88 }); // HD_NOMINAL_MAX_CONTINUOUS_FORCE
	set(0x2602, { 1.26 }); // HD_NOMINAL_MAX_STIFFNESS, N/mm
	set(CURRENT_POSITION, { 0.0, 10.0, 10.0 });
	set(CURRENT_VELOCITY, { 0.0, 0.0, 0.0 });
	set(CURRENT_TRANSFORM, { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.0, 10.0, 10.0, 1 });
	r_state.integers.push_back({ CURRENT_BUTTONS, 1, { 0 } });
	r_state.integers.push_back({ 0x2553, 1, { 6 } }); // HD_INPUT_DOF
	r_state.integers.push_back({ 0x2554, 1, { 3 } }); // HD_OUTPUT_DOF
	r_state.integers.push_back({ 0x2555, 1, { 4 } }); // HD_CALIBRATION_STYLE: inkwell
	r_state.strings = { { 0x2501, "Touch" }, { 0x2503, "3D Systems" }, { 0x2504, "FAKE-0001" }, { 0x2502, "fake 1.0" } };
	r_state.calibration = CALIBRATION_OK;
}

void run_scheduler(State *p_state) {
	State &state = *p_state;
	ThreadContext &context = thread_context();
	context.scheduler = true;
	std::vector<Scheduled> snapshot;
	snapshot.reserve(16);
	int64_t deadline = now_ns();
	while (!state.stop_requested.load(std::memory_order_acquire)) {
		{
			std::lock_guard<std::mutex> lock(state.mutex);
			snapshot = state.scheduled; // Callbacks run unlocked: they call the HD functions.
			deadline += static_cast<int64_t>(1e9 / static_cast<double>(state.rate_hz));
			state.ticks.fetch_add(1, std::memory_order_release);
		}
		std::stable_sort(snapshot.begin(), snapshot.end(), [](const Scheduled &a, const Scheduled &b) {
			return a.priority != b.priority ? a.priority > b.priority : a.order < b.order;
		});
		for (const Scheduled &entry : snapshot) {
			context.callback = entry.handle;
			const int64_t start = now_ns();
			const unsigned int code = entry.function(entry.data);
			const int64_t cost = now_ns() - start;
			context.callback = 0;
			std::lock_guard<std::mutex> lock(state.mutex);
			if (!entry.synchronous) {
				state.callback_ns[state.callback_next] = static_cast<double>(cost);
				state.callback_next = (state.callback_next + 1) % CALLBACK_COSTS;
				state.callback_filled = std::min(state.callback_filled + 1, CALLBACK_COSTS);
			}
			if (code == CALLBACK_DONE) {
				std::erase_if(state.scheduled, [&entry](const Scheduled &s) { return s.handle == entry.handle; });
				if (entry.synchronous) {
					state.finished.push_back(entry.handle);
				}
			}
		}
		state.changed.notify_all();
		if (!state.free_running.load(std::memory_order_relaxed)) {
			sleep_until(deadline);
		} else {
			deadline = now_ns();
		}
	}
}

} // namespace

State::State() {
	set_defaults(*this);
	callback_ns.assign(CALLBACK_COSTS, 0.0);
}

State::~State() {
	stop_scheduler(*this);
}

State &state() {
	static State instance;
	return instance;
}

ThreadContext &thread_context() {
	thread_local ThreadContext context;
	return context;
}

void record(State &r_state, const char *p_name, unsigned int p_pname, const double *p_values, int p_count) {
	if (!r_state.recording.load(std::memory_order_relaxed) || r_state.calls.size() >= MAX_CALLS) {
		return;
	}
	const ThreadContext &context = thread_context();
	FakeHdCall call{};
	std::snprintf(call.name, sizeof(call.name), "%s", p_name);
	call.pname = p_pname;
	call.count = std::clamp(p_count, 0, FAKE_HD_CALL_VALUES);
	for (int i = 0; i < call.count; ++i) {
		call.values[i] = p_values[i];
	}
	call.in_frame = context.frame_depth > 0;
	call.on_scheduler = context.scheduler;
	call.callback = context.callback;
	call.tick = r_state.ticks.load(std::memory_order_relaxed);
	r_state.calls.push_back(call);
}

void note_misuse(State &r_state, const std::string &p_text) {
	if (r_state.misuse++ == 0) {
		r_state.misuse_text = p_text;
	}
}

void start_scheduler(State &r_state) {
	r_state.stop_requested.store(false, std::memory_order_release);
	r_state.running.store(true, std::memory_order_release);
	r_state.thread = std::thread(run_scheduler, &r_state);
}

void stop_scheduler(State &r_state) {
	r_state.stop_requested.store(true, std::memory_order_release);
	if (r_state.thread.joinable()) {
		r_state.thread.join();
	}
	r_state.running.store(false, std::memory_order_release);
	std::lock_guard<std::mutex> lock(r_state.mutex);
	r_state.changed.notify_all();
}

} // namespace fake_hd

using namespace fake_hd;

FAKE_HD_EXPORT void fake_hd_reset(void) {
	State &s = state();
	stop_scheduler(s);
	std::lock_guard<std::mutex> lock(s.mutex);
	set_defaults(s);
	s.init_failure = ErrorInfo{};
	s.unplugged = false;
	s.injected.clear();
	s.errors.clear();
	s.initiated = false;
	s.current = INVALID_HANDLE;
	s.scheduled.clear();
	s.finished.clear();
	s.rate_hz = 1000;
	s.free_running.store(false);
	s.recording.store(true);
	s.calls.clear();
	s.calls.reserve(1 << 16);
	s.misuse = 0;
	s.misuse_text.clear();
	s.force_sets = 0;
	std::fill(std::begin(s.last_force), std::end(s.last_force), 0.0);
	s.callback_ns.assign(CALLBACK_COSTS, 0.0);
	s.callback_next = s.callback_filled = 0;
}

FAKE_HD_EXPORT void fake_hd_set_doubles(unsigned int p_pname, const double *p_values, int p_count) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	std::erase_if(s.doubles, [p_pname](const Parameter &p) { return p.pname == p_pname; });
	Parameter parameter{ p_pname, std::clamp(p_count, 0, 16), {} };
	std::copy(p_values, p_values + parameter.count, parameter.values);
	s.doubles.push_back(parameter);
}

FAKE_HD_EXPORT void fake_hd_set_integer(unsigned int p_pname, int p_value) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	std::erase_if(s.integers, [p_pname](const Parameter &p) { return p.pname == p_pname; });
	s.integers.push_back({ p_pname, 1, { static_cast<double>(p_value) } });
}

FAKE_HD_EXPORT void fake_hd_set_string(unsigned int p_pname, const char *p_value) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	std::erase_if(s.strings, [p_pname](const auto &entry) { return entry.first == p_pname; });
	std::erase(s.null_strings, p_pname);
	if (p_value != nullptr) {
		s.strings.emplace_back(p_pname, p_value);
	} else {
		s.null_strings.push_back(p_pname);
	}
}

FAKE_HD_EXPORT void fake_hd_set_calibration(unsigned int p_status) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.calibration = p_status;
}

FAKE_HD_EXPORT void fake_hd_fail_init(unsigned int p_code, int p_internal) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.init_failure = ErrorInfo{ p_code, p_internal, INVALID_HANDLE };
}

FAKE_HD_EXPORT void fake_hd_set_unplugged(int p_unplugged) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.unplugged = p_unplugged != 0;
}

FAKE_HD_EXPORT void fake_hd_inject_error(unsigned int p_code, int p_internal, unsigned int p_hhd) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.injected.push_back({ p_code, p_internal, p_hhd });
}

FAKE_HD_EXPORT void fake_hd_push_error(unsigned int p_code, int p_internal, unsigned int p_hhd) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.errors.push_back({ p_code, p_internal, p_hhd });
}

FAKE_HD_EXPORT void fake_hd_set_recording(int p_on) {
	state().recording.store(p_on != 0);
}

FAKE_HD_EXPORT void fake_hd_set_free_running(int p_on) {
	state().free_running.store(p_on != 0);
}

FAKE_HD_EXPORT size_t fake_hd_call_count(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	return s.calls.size();
}

FAKE_HD_EXPORT int fake_hd_get_call(size_t p_index, FakeHdCall *r_call) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	if (p_index >= s.calls.size()) {
		return 0;
	}
	*r_call = s.calls[p_index];
	return 1;
}

FAKE_HD_EXPORT unsigned long long fake_hd_ticks(void) {
	return state().ticks.load(std::memory_order_acquire);
}

FAKE_HD_EXPORT int fake_hd_scheduler_running(void) {
	return state().running.load(std::memory_order_acquire) ? 1 : 0;
}

FAKE_HD_EXPORT int fake_hd_wait_ticks(unsigned long long p_count, int p_timeout_ms) {
	State &s = state();
	std::unique_lock<std::mutex> lock(s.mutex);
	const uint64_t target = s.ticks.load() + p_count;
	return s.changed.wait_for(lock, std::chrono::milliseconds(p_timeout_ms),
				   [&s, target] { return s.ticks.load() >= target || !s.running.load(); }) &&
			s.ticks.load() >= target;
}

FAKE_HD_EXPORT unsigned long long fake_hd_misuse_count(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	return s.misuse;
}

FAKE_HD_EXPORT void fake_hd_misuse_text(char *r_text, size_t p_capacity) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	std::snprintf(r_text, p_capacity, "%s", s.misuse_text.c_str());
}

FAKE_HD_EXPORT size_t fake_hd_callback_costs(double *r_ns, size_t p_max) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	const size_t count = std::min(p_max, s.callback_filled);
	const size_t first = (s.callback_next + CALLBACK_COSTS - count) % CALLBACK_COSTS;
	for (size_t i = 0; i < count; ++i) {
		r_ns[i] = s.callback_ns[(first + i) % CALLBACK_COSTS];
	}
	return count;
}

FAKE_HD_EXPORT unsigned long long fake_hd_force_sets(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	return s.force_sets;
}

FAKE_HD_EXPORT void fake_hd_last_force(double r_force[3]) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	std::copy(std::begin(s.last_force), std::end(s.last_force), r_force);
}
