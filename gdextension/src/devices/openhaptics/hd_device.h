#pragma once

// A 3D Systems Touch / Phantom Omni (any HDAPI device: 6-DOF in, 3-DOF force out) driven
// through the user's OpenHaptics runtime, loaded at run time (hd_api.h).
//
// Who runs the device I/O: HD's own scheduler. We register one asynchronous callback at
// HD_MAX_SCHEDULER_PRIORITY and set the scheduler to 1 kHz; each tick it reads the stylus
// and sets the force inside hdBeginFrame/hdEndFrame, and meets our servo only through the
// DeviceExchange's seqlocks (device_exchange.h): the servo's read_state/write_force copy the
// latest state/command and never wait on HD, HD's thread never waits on the servo. We chose
// the scheduler over driving hdBeginFrame/hdEndFrame from a thread of ours because:
//  - it is the documented way (every public HDAPI user, docs/devices/openhaptics.md, "Call
//    sequences"): HD's servo loop owns
//    the timing against the device's own clock and runs its safety checks (force/velocity
//    limits, HD_EXCEEDED_MAX_VELOCITY, ramping) at that rate, so frames from another thread
//    would at best duplicate its timing and at worst race its frames;
//  - the scheduler thread is HD's (its priority, its affinity, its watchdog): nothing of ours
//    has to be real time for the device to stay safe;
//  - hdScheduleSynchronous gives a documented way to run the few one-off HD calls (initial
//    calibration, the zero force at close) on that same thread, so no two threads of ours
//    ever call frame functions concurrently.
// The callback never allocates, locks or logs: it copies through the seqlocks, converts
// units, and on an error formats one sentence into a stack buffer (once, as it stops).
//
// Each tick (docs/devices/openhaptics.md, "Call sequences"): [while not calibrated: hdCheckCalibration, hdUpdateCalibration on
// NEEDS_UPDATE (the ROS driver's pattern)] -> hdBeginFrame(hdGetCurrentDevice()) -> get
// HD_CURRENT_POSITION, _VELOCITY, _TRANSFORM, _BUTTONS -> set HD_CURRENT_FORCE -> hdEndFrame
// -> hdGetError. An error sets zero force in one more frame, reports DISCONNECTED for
// HD_COMM_ERROR (unplugged) and FAILED for anything else ("HD error 0x0201
// (HD_EXCEEDED_MAX_FORCE): ..."), and returns HD_CALLBACK_DONE; the servo then stops at its
// next read. Reopen to resume.
//
// Axes and units: hd_conversions.h (HD's frame is ours: x right, y up, z toward the user;
// mm -> m, centred on the usable workspace box; forces in N unchanged).
//
// Forces: the servo's command is clamped again here: the continuous share to
// HD_NOMINAL_MAX_CONTINUOUS_FORCE (unless the options say otherwise) and the total to
// HD_NOMINAL_MAX_FORCE; a non-finite command becomes zero (and is counted).
//
// Calibration: open() runs the calibration loop of docs/devices/openhaptics.md once on HD's thread (check; NEEDS_UPDATE ->
// hdUpdateCalibration with the device's preferred style: auto, else inkwell, else encoder
// reset). While it is not HD_CALIBRATION_OK, DeviceState::ready is false (the servo holds
// zero force), status() says why ("put the stylus in the inkwell"), and each tick checks
// again, so dropping the stylus into the inkwell makes the device ready without a call.
//
// One device per process: HD has one scheduler and one current device per process, so
// opening an HdDevice closes any other open HdDevice first (its servo then reads FAILED,
// "closed: another OpenHaptics device was opened"). HapticsSystem opens the new device
// before closing the old one, which this makes work. open() is idempotent.
//
// Tested against a fake libHD that follows docs/devices/openhaptics.md, not the runtime itself. Only a real
// Touch/Omni with OpenHaptics can confirm: the axis signs (hd_conversions.h); that an
// unplug surfaces as HD_COMM_ERROR from the frame (rather than a scheduler stall); that
// hdCheckCalibration/hdUpdateCalibration are fine outside a frame in a callback (ROS does
// it); that hdScheduleSynchronous returns while the device is gone; and the scheduler's
// real timing, priority and per-tick cost.

#include "core/base/status.h"
#include "devices/exchanged_device.h"
#include "devices/openhaptics/hd_api.h"
#include "devices/openhaptics/hd_conversions.h"

#include <atomic>
#include <cstdint>
#include <string>

namespace haptics::openhaptics {

struct HdDeviceOptions {
	// The runtime to load; empty: search (hd_runtime.h). Tests give the fake's path.
	std::string library_path;
	// hdSetSchedulerRate, in [250, 4000] Hz; the Touch's servo loop runs at 1 kHz.
	uint32_t scheduler_rate_hz = 1000;
	// Cap the continuous share at the device's nominal continuous force (motor heating).
	bool clamp_continuous_to_rating = true;
};

// What the runtime reported at open, for the HUD and the logs.
struct HdDeviceReport {
	std::string model; // HD_DEVICE_MODEL_TYPE, e.g. "Touch"
	std::string vendor;
	std::string serial;
	std::string driver_version;
	int32_t input_dof = 0;
	int32_t output_dof = 0;
	int32_t calibration_styles = 0; // HD_CALIBRATION_STYLE bit mask.
	int32_t calibration_style = 0; // The one we use.
	HdWorkspace workspace;
};

class HdDevice final : public ExchangedDevice {
public:
	explicit HdDevice(HdDeviceOptions p_options = {});
	~HdDevice() override;

	HdDevice(const HdDevice &) = delete;
	HdDevice &operator=(const HdDevice &) = delete;

	Status open() override;
	void close() override;
	// Runs hdUpdateCalibration (the device's style) on HD's thread, then checks. An error
	// when the device still needs manual input (the inkwell) or HD reports one.
	Status calibrate() override;
	DeviceCapabilities capabilities() const override { return capabilities_; }
	// The model string ("Touch"), or "OpenHaptics device" before the first open.
	const char *name() const override { return name_; }
	// Adds the calibration hint to the exchange's status.
	DeviceStatus status() const override;
	// A non-finite command goes out as zero (and is counted).
	DeviceIo write_force(const ForceCommand &p_command) override;

	const HdDeviceReport &report() const { return report_; }
	// Commands that were not finite and went out as zero.
	uint64_t non_finite_commands() const { return non_finite_commands_.load(std::memory_order_relaxed); }

private:
	static HDCallbackCode HAPTICS_HD_CALL servo_callback(void *p_device);
	static HDCallbackCode HAPTICS_HD_CALL calibration_callback(void *p_device);
	static HDCallbackCode HAPTICS_HD_CALL recalibration_callback(void *p_device);
	static HDCallbackCode HAPTICS_HD_CALL zero_force_callback(void *p_device);

	HDCallbackCode tick();
	HDenum check_calibration(bool p_force_update);
	// Ends the callback after an error: zero force, the reason into the exchange.
	HDCallbackCode stop_on_error(DeviceIo p_io, const char *p_reason);
	void set_zero_force_frame();
	void drain_errors();

	Status query_device();
	Status fail_open(Status p_status); // Undoes a partial open, returns p_status.
	void close_with_reason(const char *p_reason);

	HdDeviceOptions options_;
	HdLibrary library_;
	HHD handle_ = HD_INVALID_HANDLE;
	HDSchedulerHandle servo_handle_ = 0;
	bool device_initialised_ = false;
	bool servo_scheduled_ = false;
	bool scheduler_started_ = false;

	DeviceCapabilities capabilities_;
	HdDeviceReport report_;
	char name_[96] = "OpenHaptics device";
	// Set in open() before the scheduler starts, constant while it runs.
	double continuous_limit_n_ = 0.0;
	double peak_limit_n_ = 0.0;
	HDenum calibration_style_ = 0;

	std::atomic<bool> ready_{ false }; // Calibration OK.
	std::atomic<HDenum> calibration_status_{ 0 };
	std::atomic<bool> stopping_{ false }; // close(): the callback sets zero from now on.
	std::atomic<bool> servo_running_{ false }; // The callback has not returned DONE.
	std::atomic<uint64_t> non_finite_commands_{ 0 };
	HDErrorInfo sync_error_{}; // From the last synchronous callback (game thread waits on it).
};

} // namespace haptics::openhaptics
