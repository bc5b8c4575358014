// The HDAPI functions the backend loads (docs/devices/openhaptics.md), with the exact C signatures, served
// from the scripted state. Built twice: libfake_hd.so, and libfake_hd_no_async.so with
// FAKE_HD_WITHOUT_SCHEDULE_ASYNCHRONOUS (hdScheduleAsynchronous missing) for the loader's
// missing-symbol path.

#include "fake_hd_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace fake_hd;

namespace {

std::string hex(const char *p_what, unsigned int p_value) {
	char text[96];
	std::snprintf(text, sizeof(text), "%s(0x%04X)", p_what, p_value);
	return text;
}

const Parameter *find(const std::vector<Parameter> &p_list, unsigned int p_pname) {
	for (const Parameter &parameter : p_list) {
		if (parameter.pname == p_pname) {
			return &parameter;
		}
	}
	return nullptr;
}

void check_frame_use(State &r_state, const char *p_function, unsigned int p_pname) {
	if (is_frame_parameter(p_pname) && thread_context().frame_depth == 0) {
		note_misuse(r_state, hex(p_function, p_pname) + " outside a frame");
	}
}

template <typename T>
void get_values(const char *p_function, const std::vector<Parameter> State::*p_list, unsigned int p_pname, T *r_values) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	check_frame_use(s, p_function, p_pname);
	const Parameter *parameter = find(s.*p_list, p_pname);
	if (parameter == nullptr) {
		s.errors.push_back({ 0x0100, 0, s.current }); // HD_INVALID_ENUM
		record(s, p_function, p_pname, nullptr, 0);
		return;
	}
	for (int i = 0; i < parameter->count; ++i) {
		r_values[i] = static_cast<T>(parameter->values[i]);
	}
	record(s, p_function, p_pname, parameter->values, parameter->count);
}

void frame_edge(const char *p_function, unsigned int p_handle, bool p_begin) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	ThreadContext &context = thread_context();
	if (!s.initiated || p_handle != s.current) {
		note_misuse(s, hex(p_function, p_handle) + " on a handle that is not the current device");
	}
	if (p_begin) {
		if (context.frame_depth != 0) {
			note_misuse(s, "hdBeginFrame inside a frame");
		}
		++context.frame_depth;
	} else {
		if (context.frame_depth == 0) {
			note_misuse(s, "hdEndFrame without hdBeginFrame");
		} else {
			--context.frame_depth;
		}
		if (s.unplugged) {
			s.errors.push_back({ COMM_ERROR, 0, p_handle });
		}
		s.errors.insert(s.errors.end(), s.injected.begin(), s.injected.end());
		s.injected.clear();
	}
	record(s, p_function, p_handle, nullptr, 0);
}

} // namespace

FAKE_HD_EXPORT unsigned int hdInitDevice(const char *p_config_name) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	unsigned int handle = DEVICE_HANDLE;
	if (s.init_failure.errorCode != SUCCESS) {
		s.errors.push_back(s.init_failure);
		s.init_failure = ErrorInfo{};
		handle = INVALID_HANDLE;
	} else if (s.unplugged) {
		s.errors.push_back({ COMM_ERROR, -1, INVALID_HANDLE });
		handle = INVALID_HANDLE;
	} else if (s.initiated) {
		note_misuse(s, "hdInitDevice while a device is initiated");
		s.errors.push_back({ DEVICE_ALREADY_INITIATED, 0, INVALID_HANDLE });
		handle = INVALID_HANDLE;
	} else {
		s.initiated = true;
	}
	const double value = handle;
	record(s, "hdInitDevice", p_config_name == nullptr ? 0u : 1u, &value, 1);
	return handle;
}

FAKE_HD_EXPORT void hdMakeCurrentDevice(unsigned int p_handle) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.current = p_handle;
	record(s, "hdMakeCurrentDevice", p_handle, nullptr, 0);
}

FAKE_HD_EXPORT void hdDisableDevice(unsigned int p_handle) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	if (!s.initiated) {
		note_misuse(s, "hdDisableDevice without a device");
	}
	s.initiated = false;
	s.current = INVALID_HANDLE;
	record(s, "hdDisableDevice", p_handle, nullptr, 0);
}

FAKE_HD_EXPORT unsigned int hdGetCurrentDevice(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	const double value = s.current;
	record(s, "hdGetCurrentDevice", 0, &value, 1);
	return s.current;
}

FAKE_HD_EXPORT void hdBeginFrame(unsigned int p_handle) {
	frame_edge("hdBeginFrame", p_handle, true);
}

FAKE_HD_EXPORT void hdEndFrame(unsigned int p_handle) {
	frame_edge("hdEndFrame", p_handle, false);
}

FAKE_HD_EXPORT ErrorInfo hdGetError(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	ErrorInfo error{ SUCCESS, 0, 0 };
	if (!s.errors.empty()) {
		error = s.errors.back();
		s.errors.pop_back();
	}
	const double values[3] = { static_cast<double>(error.errorCode), static_cast<double>(error.internalErrorCode),
		static_cast<double>(error.hHD) };
	record(s, "hdGetError", 0, values, 3);
	return error;
}

FAKE_HD_EXPORT const char *hdGetErrorString(unsigned int p_code) {
	switch (p_code) {
		case EXCEEDED_MAX_FORCE:
			return "fake: the force exceeded the device's maximum";
		case COMM_ERROR:
			return "fake: communication with the device failed";
		default:
			return "fake: error";
	}
}

FAKE_HD_EXPORT void hdEnable(unsigned int p_capability) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	record(s, "hdEnable", p_capability, nullptr, 0);
}

FAKE_HD_EXPORT void hdGetIntegerv(unsigned int p_pname, int *r_values) {
	get_values("hdGetIntegerv", &State::integers, p_pname, r_values);
}

FAKE_HD_EXPORT void hdGetDoublev(unsigned int p_pname, double *r_values) {
	get_values("hdGetDoublev", &State::doubles, p_pname, r_values);
}

FAKE_HD_EXPORT const char *hdGetString(unsigned int p_pname) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	record(s, "hdGetString", p_pname, nullptr, 0);
	for (const auto &entry : s.strings) {
		if (entry.first == p_pname) {
			return entry.second.c_str(); // Stable until the script changes it.
		}
	}
	return std::find(s.null_strings.begin(), s.null_strings.end(), p_pname) != s.null_strings.end() ? nullptr : "";
}

FAKE_HD_EXPORT void hdSetDoublev(unsigned int p_pname, const double *p_values) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	check_frame_use(s, "hdSetDoublev", p_pname);
	const int count = p_pname == CURRENT_FORCE ? 3 : 1;
	if (p_pname == CURRENT_FORCE) {
		const Parameter *max_force = find(s.doubles, NOMINAL_MAX_FORCE);
		const double magnitude = std::sqrt(p_values[0] * p_values[0] + p_values[1] * p_values[1] + p_values[2] * p_values[2]);
		if (!std::isfinite(magnitude)) {
			note_misuse(s, "HD_CURRENT_FORCE not finite");
		} else if (max_force != nullptr && magnitude > max_force->values[0] * (1.0 + 1e-12)) {
			note_misuse(s, "HD_CURRENT_FORCE above HD_NOMINAL_MAX_FORCE");
		}
		++s.force_sets;
		std::copy(p_values, p_values + 3, s.last_force);
	}
	record(s, "hdSetDoublev", p_pname, p_values, count);
}

FAKE_HD_EXPORT unsigned int hdCheckCalibration(void) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	const double value = s.calibration;
	record(s, "hdCheckCalibration", 0, &value, 1);
	return s.calibration;
}

FAKE_HD_EXPORT void hdUpdateCalibration(unsigned int p_style) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	if (s.calibration == CALIBRATION_NEEDS_UPDATE) {
		s.calibration = CALIBRATION_OK;
	}
	record(s, "hdUpdateCalibration", p_style, nullptr, 0);
}

FAKE_HD_EXPORT void hdStartScheduler(void) {
	State &s = state();
	{
		std::lock_guard<std::mutex> lock(s.mutex);
		record(s, "hdStartScheduler", 0, nullptr, 0);
		if (s.running.load()) {
			note_misuse(s, "hdStartScheduler while running");
			return;
		}
	}
	start_scheduler(s);
}

FAKE_HD_EXPORT void hdStopScheduler(void) {
	State &s = state();
	{
		std::lock_guard<std::mutex> lock(s.mutex);
		record(s, "hdStopScheduler", 0, nullptr, 0);
	}
	stop_scheduler(s);
}

FAKE_HD_EXPORT void hdSetSchedulerRate(unsigned long p_rate_hz) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	s.rate_hz = std::clamp(p_rate_hz, 1ul, 100000ul);
	const double value = static_cast<double>(p_rate_hz);
	record(s, "hdSetSchedulerRate", 0, &value, 1);
}

FAKE_HD_EXPORT void hdScheduleSynchronous(Callback p_callback, void *p_data, unsigned short p_priority) {
	State &s = state();
	std::unique_lock<std::mutex> lock(s.mutex);
	const unsigned long handle = s.next_handle++;
	const double value = static_cast<double>(handle);
	record(s, "hdScheduleSynchronous", p_priority, &value, 1);
	if (s.running.load()) {
		s.scheduled.push_back({ handle, p_callback, p_data, p_priority, true, s.next_order++ });
		const auto finished = [&s, handle] {
			return std::find(s.finished.begin(), s.finished.end(), handle) != s.finished.end();
		};
		s.changed.wait(lock, [&] { return finished() || !s.running.load(); });
		if (finished()) {
			std::erase(s.finished, handle);
			return;
		}
		std::erase_if(s.scheduled, [handle](const Scheduled &entry) { return entry.handle == handle; });
	}
	// No scheduler: run it here, as often as it asks.
	lock.unlock();
	ThreadContext &context = thread_context();
	const unsigned long outer = context.callback;
	context.callback = handle;
	while (p_callback(p_data) != CALLBACK_DONE) {
	}
	context.callback = outer;
}

#ifndef FAKE_HD_WITHOUT_SCHEDULE_ASYNCHRONOUS
FAKE_HD_EXPORT unsigned long hdScheduleAsynchronous(Callback p_callback, void *p_data, unsigned short p_priority) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	const unsigned long handle = s.next_handle++;
	s.scheduled.push_back({ handle, p_callback, p_data, p_priority, false, s.next_order++ });
	const double value = static_cast<double>(handle);
	record(s, "hdScheduleAsynchronous", p_priority, &value, 1);
	return handle;
}
#endif

FAKE_HD_EXPORT void hdUnschedule(unsigned long p_handle) {
	State &s = state();
	std::lock_guard<std::mutex> lock(s.mutex);
	const size_t removed =
			std::erase_if(s.scheduled, [p_handle](const Scheduled &entry) { return entry.handle == p_handle; });
	if (removed == 0) {
		s.errors.push_back({ 0x0101, 0, s.current }); // HD_INVALID_VALUE: no such callback
	}
	record(s, "hdUnschedule", static_cast<unsigned int>(p_handle), nullptr, 0);
}
