#include "devices/openhaptics/hd_api.h"

#include "devices/dynamic_library.h"

#include <cstdio>
#include <cstring>

namespace haptics::openhaptics {

namespace {

struct ErrorName {
	HDerror code;
	const char *name;
};

// docs/devices/openhaptics.md, "Constants", in code order.
constexpr ErrorName ERROR_NAMES[] = {
	{ HD_SUCCESS, "HD_SUCCESS" },
	{ HD_INVALID_ENUM, "HD_INVALID_ENUM" },
	{ HD_INVALID_VALUE, "HD_INVALID_VALUE" },
	{ HD_INVALID_OPERATION, "HD_INVALID_OPERATION" },
	{ HD_INVALID_INPUT_TYPE, "HD_INVALID_INPUT_TYPE" },
	{ HD_BAD_HANDLE, "HD_BAD_HANDLE" },
	{ HD_WARM_MOTORS, "HD_WARM_MOTORS" },
	{ HD_EXCEEDED_MAX_FORCE, "HD_EXCEEDED_MAX_FORCE" },
	{ HD_EXCEEDED_MAX_FORCE_IMPULSE, "HD_EXCEEDED_MAX_FORCE_IMPULSE" },
	{ HD_EXCEEDED_MAX_VELOCITY, "HD_EXCEEDED_MAX_VELOCITY" },
	{ HD_FORCE_ERROR, "HD_FORCE_ERROR" },
	{ HD_DEVICE_FAULT, "HD_DEVICE_FAULT" },
	{ HD_DEVICE_ALREADY_INITIATED, "HD_DEVICE_ALREADY_INITIATED" },
	{ HD_COMM_ERROR, "HD_COMM_ERROR" },
	{ HD_COMM_CONFIG_ERROR, "HD_COMM_CONFIG_ERROR" },
	{ HD_TIMER_ERROR, "HD_TIMER_ERROR" },
	{ HD_ILLEGAL_BEGIN, "HD_ILLEGAL_BEGIN" },
	{ HD_ILLEGAL_END, "HD_ILLEGAL_END" },
	{ HD_FRAME_ERROR, "HD_FRAME_ERROR" },
	{ HD_INVALID_PRIORITY, "HD_INVALID_PRIORITY" },
	{ HD_SCHEDULER_FULL, "HD_SCHEDULER_FULL" },
	{ HD_INVALID_LICENSE, "HD_INVALID_LICENSE" },
};

template <typename F>
bool resolve(void *p_handle, const char *p_name, F &r_function) {
	void *symbol = dynamic_library_symbol(p_handle, p_name);
	if (symbol == nullptr) {
		return false;
	}
	r_function = reinterpret_cast<F>(symbol);
	return true;
}

} // namespace

const char *hd_error_name(HDerror p_code) {
	for (const ErrorName &entry : ERROR_NAMES) {
		if (entry.code == p_code) {
			return entry.name;
		}
	}
	return "unknown HD error";
}

void format_hd_error(const HdApi *p_api, const HDErrorInfo &p_error, char *r_buffer, size_t p_capacity) {
	if (p_capacity == 0) {
		return;
	}
	const char *text = nullptr;
	if (p_api != nullptr && p_api->hdGetErrorString != nullptr) {
		text = p_api->hdGetErrorString(p_error.errorCode);
	}
	if (text != nullptr && text[0] != '\0') {
		std::snprintf(r_buffer, p_capacity, "HD error 0x%04X (%s): %s, internal error %d", p_error.errorCode,
				hd_error_name(p_error.errorCode), text, p_error.internalErrorCode);
	} else {
		std::snprintf(r_buffer, p_capacity, "HD error 0x%04X (%s), internal error %d", p_error.errorCode,
				hd_error_name(p_error.errorCode), p_error.internalErrorCode);
	}
}

Status HdLibrary::load(const char *p_path) {
	unload();
	if (p_path == nullptr || p_path[0] == '\0') {
		return Status::error(StatusCode::INVALID_ARGUMENT, "OpenHaptics runtime: empty library path");
	}
	char error[256];
	bool missing = false;
	void *handle = open_dynamic_library(p_path, missing, error, sizeof(error));
	if (handle == nullptr) {
		return Status::error(missing ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR,
				"cannot load the OpenHaptics runtime '%s': %s", p_path, error);
	}
	HdApi api;
	struct Required {
		const char *name;
		bool found;
	};
	const Required required[] = {
		{ "hdInitDevice", resolve(handle, "hdInitDevice", api.hdInitDevice) },
		{ "hdMakeCurrentDevice", resolve(handle, "hdMakeCurrentDevice", api.hdMakeCurrentDevice) },
		{ "hdDisableDevice", resolve(handle, "hdDisableDevice", api.hdDisableDevice) },
		{ "hdGetCurrentDevice", resolve(handle, "hdGetCurrentDevice", api.hdGetCurrentDevice) },
		{ "hdBeginFrame", resolve(handle, "hdBeginFrame", api.hdBeginFrame) },
		{ "hdEndFrame", resolve(handle, "hdEndFrame", api.hdEndFrame) },
		{ "hdGetError", resolve(handle, "hdGetError", api.hdGetError) },
		{ "hdEnable", resolve(handle, "hdEnable", api.hdEnable) },
		{ "hdGetIntegerv", resolve(handle, "hdGetIntegerv", api.hdGetIntegerv) },
		{ "hdGetDoublev", resolve(handle, "hdGetDoublev", api.hdGetDoublev) },
		{ "hdGetString", resolve(handle, "hdGetString", api.hdGetString) },
		{ "hdSetDoublev", resolve(handle, "hdSetDoublev", api.hdSetDoublev) },
		{ "hdCheckCalibration", resolve(handle, "hdCheckCalibration", api.hdCheckCalibration) },
		{ "hdUpdateCalibration", resolve(handle, "hdUpdateCalibration", api.hdUpdateCalibration) },
		{ "hdStartScheduler", resolve(handle, "hdStartScheduler", api.hdStartScheduler) },
		{ "hdStopScheduler", resolve(handle, "hdStopScheduler", api.hdStopScheduler) },
		{ "hdSetSchedulerRate", resolve(handle, "hdSetSchedulerRate", api.hdSetSchedulerRate) },
		{ "hdScheduleSynchronous", resolve(handle, "hdScheduleSynchronous", api.hdScheduleSynchronous) },
		{ "hdScheduleAsynchronous", resolve(handle, "hdScheduleAsynchronous", api.hdScheduleAsynchronous) },
		{ "hdUnschedule", resolve(handle, "hdUnschedule", api.hdUnschedule) },
	};
	for (const Required &symbol : required) {
		if (!symbol.found) {
			close_dynamic_library(handle);
			return Status::error(StatusCode::DEVICE_ERROR,
					"the OpenHaptics runtime '%s' lacks the function %s (an unsupported OpenHaptics version?)", p_path,
					symbol.name);
		}
	}
	// Only the error messages are poorer without it.
	resolve(handle, "hdGetErrorString", api.hdGetErrorString);

	handle_ = handle;
	api_ = api;
	std::snprintf(path_, sizeof(path_), "%s", p_path);
	return Status::success();
}

void HdLibrary::unload() {
	if (handle_ != nullptr) {
		close_dynamic_library(handle_);
		handle_ = nullptr;
	}
	api_ = HdApi{};
	path_[0] = '\0';
}

} // namespace haptics::openhaptics
