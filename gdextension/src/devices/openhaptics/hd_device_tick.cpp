// HdDevice's side on HD's scheduler thread: the servo callback and the one-off synchronous
// callbacks (calibration, zero force at close). Nothing here allocates, locks or logs.

#include "devices/openhaptics/hd_device.h"

#include "core/base/realtime.h"

#include <cstdio>

namespace haptics::openhaptics {

namespace {

// hdGetError pops one error; a burst (e.g. unplugged mid-frame) is drained this far.
constexpr int MAX_DRAINED_ERRORS = 16;

} // namespace

HDCallbackCode HAPTICS_HD_CALL HdDevice::servo_callback(void *p_device) {
	return static_cast<HdDevice *>(p_device)->tick();
}

HDCallbackCode HAPTICS_HD_CALL HdDevice::calibration_callback(void *p_device) {
	HdDevice &device = *static_cast<HdDevice *>(p_device);
	device.check_calibration(false);
	device.sync_error_ = device.library_.api().hdGetError();
	return HD_CALLBACK_DONE;
}

HDCallbackCode HAPTICS_HD_CALL HdDevice::recalibration_callback(void *p_device) {
	HdDevice &device = *static_cast<HdDevice *>(p_device);
	device.check_calibration(true);
	device.sync_error_ = device.library_.api().hdGetError();
	return HD_CALLBACK_DONE;
}

HDCallbackCode HAPTICS_HD_CALL HdDevice::zero_force_callback(void *p_device) {
	HdDevice &device = *static_cast<HdDevice *>(p_device);
	device.set_zero_force_frame();
	device.drain_errors(); // Closing: the device may well be gone.
	return HD_CALLBACK_DONE;
}

HDenum HdDevice::check_calibration(bool p_force_update) {
	const HdApi &hd = library_.api();
	HDenum status = hd.hdCheckCalibration();
	if (calibration_style_ != 0 && (p_force_update || status == HD_CALIBRATION_NEEDS_UPDATE)) {
		hd.hdUpdateCalibration(calibration_style_);
		status = hd.hdCheckCalibration();
	}
	calibration_status_.store(status, std::memory_order_release);
	ready_.store(status == HD_CALIBRATION_OK, std::memory_order_release);
	return status;
}

HDCallbackCode HdDevice::tick() {
	const int64_t start_ns = monotonic_now_ns();
	const HdApi &hd = library_.api();
	bool ready = ready_.load(std::memory_order_relaxed);
	if (!ready) {
		ready = check_calibration(false) == HD_CALIBRATION_OK;
	}
	// The servo's newest command, bounded again at the motors' boundary. Uncalibrated
	// positions are wrong, so no force until calibrated (the servo holds zero too).
	const ForceCommand command = exchange_.latest_command();
	const Vec3 force = stopping_.load(std::memory_order_acquire) || !ready
			? Vec3{}
			: bounded_force(command, options_.clamp_continuous_to_rating ? continuous_limit_n_ : 0.0, peak_limit_n_);
	const double force_n[3] = { force.x, force.y, force.z };
	double position_mm[3];
	double velocity_mm_s[3];
	double transform[16];
	HDint buttons = 0;

	const HHD device = hd.hdGetCurrentDevice();
	hd.hdBeginFrame(device);
	hd.hdGetDoublev(HD_CURRENT_POSITION, position_mm);
	hd.hdGetDoublev(HD_CURRENT_VELOCITY, velocity_mm_s);
	hd.hdGetDoublev(HD_CURRENT_TRANSFORM, transform);
	hd.hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);
	hd.hdSetDoublev(HD_CURRENT_FORCE, force_n);
	hd.hdEndFrame(device);
	const HDErrorInfo error = hd.hdGetError();
	if (hd_failed(error)) {
		char reason[DEVICE_REASON_CAPACITY];
		format_hd_error(&hd, error, reason, sizeof(reason));
		return stop_on_error(error.errorCode == HD_COMM_ERROR ? DeviceIo::DISCONNECTED : DeviceIo::FAILED, reason);
	}

	DeviceState state;
	state.position_m = position_from_hd(position_mm, report_.workspace.centre_m);
	state.velocity_m_per_s = velocity_from_hd(velocity_mm_s);
	if (!is_finite(state.position_m) || !is_finite(state.velocity_m_per_s)) {
		char reason[DEVICE_REASON_CAPACITY];
		std::snprintf(reason, sizeof(reason), "OpenHaptics: the device reported a non-finite %s",
				is_finite(state.position_m) ? "HD_CURRENT_VELOCITY" : "HD_CURRENT_POSITION");
		return stop_on_error(DeviceIo::FAILED, reason);
	}
	if (!position_plausible(state.position_m)) {
		char reason[DEVICE_REASON_CAPACITY];
		std::snprintf(reason, sizeof(reason),
				"OpenHaptics: the device reported an HD_CURRENT_POSITION %.3g m from the workspace centre (no device reaches %g m)",
				length(state.position_m), MAX_PLAUSIBLE_POSITION_M);
		return stop_on_error(DeviceIo::FAILED, reason);
	}
	state.orientation = orientation_from_hd_transform(transform);
	state.buttons = static_cast<uint32_t>(buttons); // HD_DEVICE_BUTTON_n is bit n-1: ours.
	state.ready = ready;
	exchange_.publish_state(state);
	exchange_.record_cycle(static_cast<double>(monotonic_now_ns() - start_ns) * 1e-9);
	return HD_CALLBACK_CONTINUE;
}

HDCallbackCode HdDevice::stop_on_error(DeviceIo p_io, const char *p_reason) {
	set_zero_force_frame();
	drain_errors();
	exchange_.fail(p_io, "%s", p_reason);
	servo_running_.store(false, std::memory_order_release);
	return HD_CALLBACK_DONE;
}

void HdDevice::set_zero_force_frame() {
	const HdApi &hd = library_.api();
	const double zero[3] = { 0.0, 0.0, 0.0 };
	const HHD device = hd.hdGetCurrentDevice();
	hd.hdBeginFrame(device);
	hd.hdSetDoublev(HD_CURRENT_FORCE, zero);
	hd.hdEndFrame(device);
}

void HdDevice::drain_errors() {
	const HdApi &hd = library_.api();
	for (int i = 0; i < MAX_DRAINED_ERRORS && hd_failed(hd.hdGetError()); ++i) {
	}
}

} // namespace haptics::openhaptics
