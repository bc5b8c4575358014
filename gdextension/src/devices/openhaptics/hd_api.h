#pragma once

// Our own declarations of the part of OpenHaptics' HDAPI we call, and a run-time loader for
// it. OpenHaptics is proprietary: we never include SensAble's headers, never link libHD and
// never ship it; the user's install is dlopen'ed and every function is looked up by its C
// name. Types and values restate docs/devices/openhaptics.md ("Types", "Calling convention",
// "Functions we call", "Constants"); nothing here is copied from the headers.
//
// ABI points that matter (docs/devices/openhaptics.md, "Types" and "Calling convention"):
//  - HHD is unsigned int but HDSchedulerHandle is unsigned long (8 bytes on LP64).
//  - hdGetError returns a 12-byte struct BY VALUE (RAX:RDX on x86-64 SysV), so its pointer
//    is declared with the struct return type, never as an int.
//  - Linux headers mark API functions and callbacks stdcall; GCC ignores that on x86-64 but
//    not on i386, where both sides must keep it (HAPTICS_HD_CALL).

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>

#if defined(__i386__)
#define HAPTICS_HD_CALL __attribute__((stdcall))
#else
#define HAPTICS_HD_CALL
#endif

namespace haptics::openhaptics {

// --- Types (docs/devices/openhaptics.md) ------------------------------------------------------
using HDuint = unsigned int;
using HDboolean = unsigned char;
using HDulong = unsigned long;
using HDushort = unsigned short;
using HDint = int;
using HDdouble = double;
using HDerror = unsigned int;
using HDenum = unsigned int;
using HDstring = const char *;
using HHD = unsigned int;
using HDCallbackCode = unsigned int;
using HDSchedulerHandle = unsigned long;

struct HDErrorInfo {
	HDerror errorCode;
	int internalErrorCode;
	HHD hHD;
};
static_assert(sizeof(HDErrorInfo) == 12, "docs/devices/openhaptics.md: HDErrorInfo is three 4-byte fields");

using HDSchedulerCallback = HDCallbackCode(HAPTICS_HD_CALL *)(void *p_user_data);

// --- Constants (docs/devices/openhaptics.md) --------------------------------------------------
inline constexpr HDstring HD_DEFAULT_DEVICE = nullptr;
inline constexpr HHD HD_INVALID_HANDLE = 0xFFFFFFFFu;
inline constexpr HDCallbackCode HD_CALLBACK_DONE = 0;
inline constexpr HDCallbackCode HD_CALLBACK_CONTINUE = 1;
inline constexpr HDushort HD_MAX_SCHEDULER_PRIORITY = 65535;

// Parameters (hdGet*/hdSet*).
inline constexpr HDenum HD_CURRENT_BUTTONS = 0x2000;
inline constexpr HDenum HD_CURRENT_POSITION = 0x2050;
inline constexpr HDenum HD_CURRENT_VELOCITY = 0x2051;
inline constexpr HDenum HD_CURRENT_TRANSFORM = 0x2052;
inline constexpr HDenum HD_DEVICE_MODEL_TYPE = 0x2501;
inline constexpr HDenum HD_DEVICE_DRIVER_VERSION = 0x2502;
inline constexpr HDenum HD_DEVICE_VENDOR = 0x2503;
inline constexpr HDenum HD_DEVICE_SERIAL_NUMBER = 0x2504;
inline constexpr HDenum HD_USABLE_WORKSPACE_DIMENSIONS = 0x2551;
inline constexpr HDenum HD_INPUT_DOF = 0x2553;
inline constexpr HDenum HD_OUTPUT_DOF = 0x2554;
inline constexpr HDenum HD_CALIBRATION_STYLE = 0x2555;
inline constexpr HDenum HD_NOMINAL_MAX_STIFFNESS = 0x2602;
inline constexpr HDenum HD_NOMINAL_MAX_FORCE = 0x2603;
inline constexpr HDenum HD_NOMINAL_MAX_CONTINUOUS_FORCE = 0x2604;
inline constexpr HDenum HD_CURRENT_FORCE = 0x2700;

// Capabilities (hdEnable).
inline constexpr HDenum HD_FORCE_OUTPUT = 0x4000;

// Calibration: hdCheckCalibration's answers and the styles (a bit mask in HD_CALIBRATION_STYLE).
inline constexpr HDenum HD_CALIBRATION_OK = 0x5000;
inline constexpr HDenum HD_CALIBRATION_NEEDS_UPDATE = 0x5001;
inline constexpr HDenum HD_CALIBRATION_NEEDS_MANUAL_INPUT = 0x5002;
inline constexpr HDint HD_CALIBRATION_ENCODER_RESET = 1;
inline constexpr HDint HD_CALIBRATION_AUTO = 2;
inline constexpr HDint HD_CALIBRATION_INKWELL = 4;

// Error codes.
inline constexpr HDerror HD_SUCCESS = 0x0000;
inline constexpr HDerror HD_INVALID_ENUM = 0x0100;
inline constexpr HDerror HD_INVALID_VALUE = 0x0101;
inline constexpr HDerror HD_INVALID_OPERATION = 0x0102;
inline constexpr HDerror HD_INVALID_INPUT_TYPE = 0x0103;
inline constexpr HDerror HD_BAD_HANDLE = 0x0104;
inline constexpr HDerror HD_WARM_MOTORS = 0x0200;
inline constexpr HDerror HD_EXCEEDED_MAX_FORCE = 0x0201;
inline constexpr HDerror HD_EXCEEDED_MAX_FORCE_IMPULSE = 0x0202;
inline constexpr HDerror HD_EXCEEDED_MAX_VELOCITY = 0x0203;
inline constexpr HDerror HD_FORCE_ERROR = 0x0204;
inline constexpr HDerror HD_DEVICE_FAULT = 0x0300;
inline constexpr HDerror HD_DEVICE_ALREADY_INITIATED = 0x0301;
inline constexpr HDerror HD_COMM_ERROR = 0x0302;
inline constexpr HDerror HD_COMM_CONFIG_ERROR = 0x0303;
inline constexpr HDerror HD_TIMER_ERROR = 0x0304;
inline constexpr HDerror HD_ILLEGAL_BEGIN = 0x0400;
inline constexpr HDerror HD_ILLEGAL_END = 0x0401;
inline constexpr HDerror HD_FRAME_ERROR = 0x0402;
inline constexpr HDerror HD_INVALID_PRIORITY = 0x0500;
inline constexpr HDerror HD_SCHEDULER_FULL = 0x0501;
inline constexpr HDerror HD_INVALID_LICENSE = 0x0600;

// --- The functions we call (docs/devices/openhaptics.md), as pointers filled by HdLibrary::load
struct HdApi {
	HHD(HAPTICS_HD_CALL *hdInitDevice)
	(HDstring p_config_name) = nullptr;
	void(HAPTICS_HD_CALL *hdMakeCurrentDevice)(HHD p_handle) = nullptr;
	void(HAPTICS_HD_CALL *hdDisableDevice)(HHD p_handle) = nullptr;
	HHD(HAPTICS_HD_CALL *hdGetCurrentDevice)
	() = nullptr;
	void(HAPTICS_HD_CALL *hdBeginFrame)(HHD p_handle) = nullptr;
	void(HAPTICS_HD_CALL *hdEndFrame)(HHD p_handle) = nullptr;
	HDErrorInfo(HAPTICS_HD_CALL *hdGetError)() = nullptr;
	HDstring(HAPTICS_HD_CALL *hdGetErrorString)(HDerror p_code) = nullptr; // Optional.
	void(HAPTICS_HD_CALL *hdEnable)(HDenum p_capability) = nullptr;
	void(HAPTICS_HD_CALL *hdGetIntegerv)(HDenum p_name, HDint *r_values) = nullptr;
	void(HAPTICS_HD_CALL *hdGetDoublev)(HDenum p_name, HDdouble *r_values) = nullptr;
	HDstring(HAPTICS_HD_CALL *hdGetString)(HDenum p_name) = nullptr;
	void(HAPTICS_HD_CALL *hdSetDoublev)(HDenum p_name, const HDdouble *p_values) = nullptr;
	HDenum(HAPTICS_HD_CALL *hdCheckCalibration)() = nullptr;
	void(HAPTICS_HD_CALL *hdUpdateCalibration)(HDenum p_style) = nullptr;
	void(HAPTICS_HD_CALL *hdStartScheduler)() = nullptr;
	void(HAPTICS_HD_CALL *hdStopScheduler)() = nullptr;
	void(HAPTICS_HD_CALL *hdSetSchedulerRate)(HDulong p_rate_hz) = nullptr;
	void(HAPTICS_HD_CALL *hdScheduleSynchronous)(HDSchedulerCallback p_callback, void *p_user_data,
			HDushort p_priority) = nullptr;
	HDSchedulerHandle(HAPTICS_HD_CALL *hdScheduleAsynchronous)(HDSchedulerCallback p_callback, void *p_user_data,
			HDushort p_priority) = nullptr;
	void(HAPTICS_HD_CALL *hdUnschedule)(HDSchedulerHandle p_handle) = nullptr;
};

// The header's HD_DEVICE_ERROR(e) (docs/devices/openhaptics.md).
inline bool hd_failed(const HDErrorInfo &p_error) {
	return p_error.errorCode != HD_SUCCESS;
}

// "HD_EXCEEDED_MAX_FORCE" for 0x0201; "unknown HD error" for codes not in docs/devices/openhaptics.md.
const char *hd_error_name(HDerror p_code);

// One sentence for a status line: "HD error 0x0201 (HD_EXCEEDED_MAX_FORCE): <the runtime's
// hdGetErrorString text>, internal error 123". p_api may be null or lack hdGetErrorString.
// Writes into r_buffer (always terminated); never allocates, so the scheduler callback can
// use it.
void format_hd_error(const HdApi *p_api, const HDErrorInfo &p_error, char *r_buffer, size_t p_capacity);

// A loaded HD runtime (dynamic_library.h: dlopen, LoadLibrary) and its resolved functions. Loading resolves EVERY required
// symbol up front, so a runtime too old or a wrong library fails here with the missing name,
// not later inside the servo. Game thread only; the functions may then be called from any
// thread the runtime allows.
class HdLibrary {
public:
	HdLibrary() = default;
	~HdLibrary() { unload(); }
	HdLibrary(const HdLibrary &) = delete;
	HdLibrary &operator=(const HdLibrary &) = delete;

	// open_dynamic_library(p_path) (dynamic_library.h), then each function. p_path is a file path or a
	// bare name the system's loader searches for. Errors (the message has the loader's
	// text): NO_DEVICE when there is no such file, DEVICE_ERROR when it is there but cannot be
	// loaded (a missing dependency, not a library) or lacks a function (named).
	Status load(const char *p_path);
	void unload(); // dlclose; idempotent.
	bool is_loaded() const { return handle_ != nullptr; }
	const HdApi &api() const { return api_; }
	const char *path() const { return path_; }

private:
	void *handle_ = nullptr;
	HdApi api_;
	char path_[512] = {};
};

} // namespace haptics::openhaptics
