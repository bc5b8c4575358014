#pragma once

// The fake OpenHaptics runtime as the tests and the bench see it: the library is dlopen'ed
// once by path (HAPTICS_FAKE_HD_PATH, from CMake) and its fake_hd_* control functions are
// resolved from that handle. The backend under test dlopens the same path, so both share
// one instance; this handle also keeps it loaded between devices, so the record survives
// the backend's dlclose.

#include "fake_hd/fake_hd_control.h"

#include "devices/dynamic_library.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace haptics::test {

struct FakeHd {
	void (*reset)();
	void (*set_doubles)(unsigned int, const double *, int);
	void (*set_integer)(unsigned int, int);
	void (*set_string)(unsigned int, const char *);
	void (*set_calibration)(unsigned int);
	void (*fail_init)(unsigned int, int);
	void (*set_unplugged)(int);
	void (*inject_error)(unsigned int, int, unsigned int);
	void (*push_error)(unsigned int, int, unsigned int);
	void (*set_recording)(int);
	void (*set_free_running)(int);
	size_t (*call_count)();
	int (*get_call)(size_t, FakeHdCall *);
	unsigned long long (*ticks)();
	int (*scheduler_running)();
	int (*wait_ticks)(unsigned long long, int);
	unsigned long long (*misuse_count)();
	void (*misuse_text)(char *, size_t);
	size_t (*callback_costs)(double *, size_t);
	unsigned long long (*force_sets)();
	void (*last_force)(double *);

	std::vector<FakeHdCall> calls() const {
		std::vector<FakeHdCall> result(call_count());
		size_t n = 0;
		while (n < result.size() && get_call(n, &result[n])) {
			++n;
		}
		result.resize(n);
		return result;
	}

	std::string first_misuse() const {
		char text[256];
		misuse_text(text, sizeof(text));
		return text;
	}
};

template <typename F>
void fake_hd_resolve(void *p_handle, const char *p_name, F &r_function) {
	void *symbol = dynamic_library_symbol(p_handle, p_name);
	if (symbol == nullptr) {
		std::fprintf(stderr, "fake HD: %s missing\n", p_name);
		std::abort();
	}
	r_function = reinterpret_cast<F>(symbol);
}

inline const char *fake_hd_path() {
	return HAPTICS_FAKE_HD_PATH;
}

// Aborts when the fake cannot be loaded: every OpenHaptics test needs it.
inline FakeHd &fake_hd() {
	static FakeHd fake = [] {
		char error[256];
		bool missing = false;
		void *handle = open_dynamic_library(HAPTICS_FAKE_HD_PATH, missing, error, sizeof(error));
		if (handle == nullptr) {
			std::fprintf(stderr, "cannot load the fake HD library: %s\n", error);
			std::abort();
		}
		FakeHd f{};
		fake_hd_resolve(handle, "fake_hd_reset", f.reset);
		fake_hd_resolve(handle, "fake_hd_set_doubles", f.set_doubles);
		fake_hd_resolve(handle, "fake_hd_set_integer", f.set_integer);
		fake_hd_resolve(handle, "fake_hd_set_string", f.set_string);
		fake_hd_resolve(handle, "fake_hd_set_calibration", f.set_calibration);
		fake_hd_resolve(handle, "fake_hd_fail_init", f.fail_init);
		fake_hd_resolve(handle, "fake_hd_set_unplugged", f.set_unplugged);
		fake_hd_resolve(handle, "fake_hd_inject_error", f.inject_error);
		fake_hd_resolve(handle, "fake_hd_push_error", f.push_error);
		fake_hd_resolve(handle, "fake_hd_set_recording", f.set_recording);
		fake_hd_resolve(handle, "fake_hd_set_free_running", f.set_free_running);
		fake_hd_resolve(handle, "fake_hd_call_count", f.call_count);
		fake_hd_resolve(handle, "fake_hd_get_call", f.get_call);
		fake_hd_resolve(handle, "fake_hd_ticks", f.ticks);
		fake_hd_resolve(handle, "fake_hd_scheduler_running", f.scheduler_running);
		fake_hd_resolve(handle, "fake_hd_wait_ticks", f.wait_ticks);
		fake_hd_resolve(handle, "fake_hd_misuse_count", f.misuse_count);
		fake_hd_resolve(handle, "fake_hd_misuse_text", f.misuse_text);
		fake_hd_resolve(handle, "fake_hd_callback_costs", f.callback_costs);
		fake_hd_resolve(handle, "fake_hd_force_sets", f.force_sets);
		fake_hd_resolve(handle, "fake_hd_last_force", f.last_force);
		return f;
	}();
	return fake;
}

// Polls p_done every millisecond for up to p_seconds; whether it became true.
template <typename F>
bool wait_for(F &&p_done, double p_seconds = 2.0) {
	const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (!p_done()) {
		if (std::chrono::steady_clock::now() > end) {
			return false;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	return true;
}

// A fresh fake: defaults, empty record.
inline FakeHd &fresh_fake_hd() {
	FakeHd &fake = fake_hd();
	fake.reset();
	return fake;
}

} // namespace haptics::test
