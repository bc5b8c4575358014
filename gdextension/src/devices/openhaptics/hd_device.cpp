#include "devices/openhaptics/hd_device.h"

#include "devices/openhaptics/hd_runtime.h"

#include <cmath>
#include <cstdio>
#include <mutex>
#include <utility>

namespace haptics::openhaptics {

namespace {

constexpr char DEFAULT_NAME[] = "OpenHaptics device";
constexpr char INKWELL_REASON[] = "OpenHaptics device not calibrated: put the stylus in the inkwell";
constexpr char CALIBRATING_REASON[] = "OpenHaptics device calibrating";
// Touch and Omni styluses have two buttons (HD_DEVICE_BUTTON_1, _2); HD defines four bits.
constexpr int32_t STYLUS_BUTTONS = 2;
constexpr double MAX_SANE_FORCE_N = 100.0;

// HD has one scheduler and one current device per process: at most one HdDevice is open.
std::mutex active_mutex;
HdDevice *active_device = nullptr;

const char *calibration_name(HDenum p_status) {
	switch (p_status) {
		case HD_CALIBRATION_OK:
			return "HD_CALIBRATION_OK";
		case HD_CALIBRATION_NEEDS_UPDATE:
			return "HD_CALIBRATION_NEEDS_UPDATE";
		case HD_CALIBRATION_NEEDS_MANUAL_INPUT:
			return "HD_CALIBRATION_NEEDS_MANUAL_INPUT";
		default:
			return "unknown calibration status";
	}
}

// The ROS and HD examples' preference: auto, else inkwell, else encoder reset.
HDenum preferred_calibration_style(int32_t p_styles) {
	if (p_styles & HD_CALIBRATION_AUTO) {
		return HD_CALIBRATION_AUTO;
	}
	if (p_styles & HD_CALIBRATION_INKWELL) {
		return HD_CALIBRATION_INKWELL;
	}
	if (p_styles & HD_CALIBRATION_ENCODER_RESET) {
		return HD_CALIBRATION_ENCODER_RESET;
	}
	return 0;
}

// The HD error first, the hint last: a long runtime text truncates the hint, not the code.
Status hd_status(StatusCode p_code, const HdApi &p_api, const char *p_what, const HDErrorInfo &p_error,
		const char *p_hint = "") {
	char error[160];
	format_hd_error(&p_api, p_error, error, sizeof(error));
	return Status::error(p_code, "OpenHaptics: %s failed: %s%s", p_what, error, p_hint);
}

} // namespace

HdDevice::HdDevice(HdDeviceOptions p_options) :
		options_(std::move(p_options)) {
	// Until open() succeeds the servo-side calls say so instead of serving a zero state.
	exchange_.fail(DeviceIo::FAILED, "OpenHaptics device not open");
}

HdDevice::~HdDevice() {
	close();
}

Status HdDevice::open() {
	if (open_) {
		return Status::success();
	}
	if (options_.scheduler_rate_hz < 250 || options_.scheduler_rate_hz > 4000) {
		return Status::error(StatusCode::OUT_OF_RANGE, "OpenHaptics: scheduler_rate_hz must be in [250, 4000] (got %u)",
				options_.scheduler_rate_hz);
	}
	HdDevice *previous = nullptr;
	{
		const std::lock_guard<std::mutex> lock(active_mutex);
		previous = active_device;
	}
	if (previous != nullptr && previous != this) {
		previous->close_with_reason("closed: another OpenHaptics device was opened in this process");
	}

	const Status loaded = load_hd_runtime(options_.library_path.c_str(), library_);
	if (!loaded) {
		return loaded;
	}
	const HdApi &hd = library_.api();

	// docs/devices/openhaptics.md, "Call sequences": init -> check -> make current -> query -> enable force -> schedule -> rate
	// -> start -> check -> calibrate.
	handle_ = hd.hdInitDevice(HD_DEFAULT_DEVICE);
	const HDErrorInfo init_error = hd.hdGetError();
	if (hd_failed(init_error) || handle_ == HD_INVALID_HANDLE) {
		device_initialised_ = handle_ != HD_INVALID_HANDLE; // A handle with an error: disable it.
		if (!hd_failed(init_error)) {
			return fail_open(Status::error(StatusCode::DEVICE_ERROR,
					"OpenHaptics: hdInitDevice(HD_DEFAULT_DEVICE) returned HD_INVALID_HANDLE without an error"));
		}
		// A Touch that is unplugged or not configured fails here with a communication error.
		const bool absent = init_error.errorCode == HD_COMM_ERROR || init_error.errorCode == HD_COMM_CONFIG_ERROR;
		return fail_open(hd_status(absent ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR, hd,
				"hdInitDevice(HD_DEFAULT_DEVICE)", init_error,
				absent ? "; is the device plugged in and set up in its driver's tool?" : ""));
	}
	device_initialised_ = true;
	hd.hdMakeCurrentDevice(handle_);

	const Status queried = query_device();
	if (!queried) {
		return fail_open(queried);
	}

	exchange_.reset(DeviceState{ {}, {}, {}, 0, false });
	ready_.store(false, std::memory_order_relaxed);
	stopping_.store(false, std::memory_order_relaxed);
	calibration_status_.store(0, std::memory_order_relaxed);
	servo_running_.store(true, std::memory_order_release);

	hd.hdEnable(HD_FORCE_OUTPUT);
	servo_handle_ = hd.hdScheduleAsynchronous(&HdDevice::servo_callback, this, HD_MAX_SCHEDULER_PRIORITY);
	servo_scheduled_ = true;
	hd.hdSetSchedulerRate(options_.scheduler_rate_hz);
	hd.hdStartScheduler();
	scheduler_started_ = true;
	const HDErrorInfo start_error = hd.hdGetError();
	if (hd_failed(start_error)) {
		return fail_open(hd_status(StatusCode::DEVICE_ERROR, hd, "starting the HD scheduler", start_error));
	}

	// Calibration on HD's thread (see the header); NEEDS_MANUAL_INPUT is not an error.
	sync_error_ = HDErrorInfo{};
	hd.hdScheduleSynchronous(&HdDevice::calibration_callback, this, HD_MAX_SCHEDULER_PRIORITY);
	if (hd_failed(sync_error_)) {
		return fail_open(hd_status(StatusCode::DEVICE_ERROR, hd, "checking the calibration", sync_error_));
	}

	{
		const std::lock_guard<std::mutex> lock(active_mutex);
		active_device = this;
	}
	open_ = true;
	return Status::success();
}

Status HdDevice::query_device() {
	const HdApi &hd = library_.api();
	const auto text = [&hd](HDenum p_name) {
		const char *value = hd.hdGetString(p_name);
		return std::string(value != nullptr ? value : "");
	};
	report_ = HdDeviceReport{};
	report_.model = text(HD_DEVICE_MODEL_TYPE);
	report_.vendor = text(HD_DEVICE_VENDOR);
	report_.serial = text(HD_DEVICE_SERIAL_NUMBER);
	report_.driver_version = text(HD_DEVICE_DRIVER_VERSION);

	// Filled with NaN / -1 first, so a runtime that writes nothing is caught below.
	const double nan = std::nan("");
	double max_force = nan;
	double max_continuous = nan;
	double stiffness_n_per_mm = nan;
	double box_mm[6] = { nan, nan, nan, nan, nan, nan };
	HDint input_dof = -1;
	HDint output_dof = -1;
	HDint styles = 0;
	hd.hdGetDoublev(HD_NOMINAL_MAX_FORCE, &max_force);
	hd.hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &max_continuous);
	hd.hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &stiffness_n_per_mm);
	hd.hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, box_mm);
	hd.hdGetIntegerv(HD_INPUT_DOF, &input_dof);
	hd.hdGetIntegerv(HD_OUTPUT_DOF, &output_dof);
	hd.hdGetIntegerv(HD_CALIBRATION_STYLE, &styles);
	const HDErrorInfo error = hd.hdGetError();
	if (hd_failed(error)) {
		return hd_status(StatusCode::DEVICE_ERROR, hd, "reading the device's parameters", error);
	}

	if (!std::isfinite(max_force) || !(max_force > 0.0) || max_force > MAX_SANE_FORCE_N) {
		return Status::error(StatusCode::DEVICE_ERROR, "OpenHaptics: HD_NOMINAL_MAX_FORCE is %g N (expected (0, %g])",
				max_force, MAX_SANE_FORCE_N);
	}
	if (!std::isfinite(max_continuous) || !(max_continuous > 0.0)) {
		return Status::error(StatusCode::DEVICE_ERROR,
				"OpenHaptics: HD_NOMINAL_MAX_CONTINUOUS_FORCE is %g N (expected > 0)", max_continuous);
	}
	const Status workspace = workspace_from_hd_box(box_mm, report_.workspace);
	if (!workspace) {
		return Status::error(StatusCode::DEVICE_ERROR, "OpenHaptics: %s", workspace.message());
	}
	if (input_dof < 3 || output_dof < 3) {
		return Status::error(StatusCode::UNSUPPORTED,
				"OpenHaptics: HD_INPUT_DOF %d / HD_OUTPUT_DOF %d: a device with 3-DOF position and force is needed",
				input_dof, output_dof);
	}
	report_.input_dof = input_dof;
	report_.output_dof = output_dof;
	report_.calibration_styles = styles;
	calibration_style_ = preferred_calibration_style(styles);
	report_.calibration_style = static_cast<int32_t>(calibration_style_);

	peak_limit_n_ = max_force;
	// A rating above the peak is a runtime's slip: the peak bounds it.
	continuous_limit_n_ = std::fmin(max_continuous, max_force);

	DeviceCapabilities capabilities;
	capabilities.input_dof = input_dof >= 6 ? 6 : 3;
	capabilities.output_dof = 3; // We command forces only, also on 6-DOF-out models.
	capabilities.output = ForceOutput::DIRECTIONAL;
	capabilities.limits.max_force_n = max_force;
	capabilities.limits.max_continuous_force_n = continuous_limit_n_;
	// Informative only (the core does not enforce it); unknown (0) when HD gives nonsense.
	capabilities.limits.max_stiffness_n_per_m =
			std::isfinite(stiffness_n_per_mm) && stiffness_n_per_mm > 0.0 ? stiffness_n_per_mm * N_PER_MM_TO_N_PER_M : 0.0;
	capabilities.limits.workspace_radius_m = report_.workspace.radius_m;
	capabilities.native_rate_hz = static_cast<double>(options_.scheduler_rate_hz);
	capabilities.has_orientation = input_dof >= 6;
	capabilities.needs_homing = true; // Calibration gates the force through DeviceState::ready.
	capabilities.physical = true;
	capabilities.button_count = STYLUS_BUTTONS;
	capabilities_ = capabilities;
	std::snprintf(name_, sizeof(name_), "%s", report_.model.empty() ? DEFAULT_NAME : report_.model.c_str());
	return Status::success();
}

Status HdDevice::fail_open(Status p_status) {
	// Same order as close(), for what got that far.
	if (library_.is_loaded()) {
		const HdApi &hd = library_.api();
		if (scheduler_started_) {
			hd.hdStopScheduler();
		}
		if (servo_scheduled_ && servo_running_.load(std::memory_order_acquire)) {
			hd.hdUnschedule(servo_handle_);
		}
		if (device_initialised_) {
			hd.hdDisableDevice(handle_);
		}
		drain_errors();
	}
	scheduler_started_ = servo_scheduled_ = device_initialised_ = false;
	servo_running_.store(false, std::memory_order_release);
	handle_ = HD_INVALID_HANDLE;
	library_.unload();
	if (exchange_.status().io == DeviceIo::OK) {
		exchange_.fail(DeviceIo::FAILED, "OpenHaptics device not open");
	}
	return p_status;
}

void HdDevice::close() {
	close_with_reason("OpenHaptics device closed");
}

void HdDevice::close_with_reason(const char *p_reason) {
	if (!open_) {
		return;
	}
	const HdApi &hd = library_.api();
	// From now on the callback sets zero; then one frame of zero on HD's thread, which also
	// covers a callback that already stopped on an error.
	stopping_.store(true, std::memory_order_release);
	hd.hdScheduleSynchronous(&HdDevice::zero_force_callback, this, HD_MAX_SCHEDULER_PRIORITY);
	// docs/devices/openhaptics.md, "Call sequences": stop -> unschedule -> disable.
	hd.hdStopScheduler();
	if (servo_running_.load(std::memory_order_acquire)) {
		hd.hdUnschedule(servo_handle_);
	}
	hd.hdDisableDevice(handle_);
	drain_errors(); // A later open must not read this session's errors as its own.
	scheduler_started_ = servo_scheduled_ = device_initialised_ = false;
	servo_running_.store(false, std::memory_order_release);
	handle_ = HD_INVALID_HANDLE;
	library_.unload();
	// A servo still running on this device stops at its next read; an earlier fault's
	// reason (the unplug) is kept.
	if (exchange_.status().io == DeviceIo::OK) {
		exchange_.fail(DeviceIo::FAILED, "%s", p_reason);
	}
	ready_.store(false, std::memory_order_relaxed);
	open_ = false;
	const std::lock_guard<std::mutex> lock(active_mutex);
	if (active_device == this) {
		active_device = nullptr;
	}
}

Status HdDevice::calibrate() {
	if (!open_) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", name());
	}
	if (exchange_.status().io != DeviceIo::OK) {
		return Status::error(StatusCode::DEVICE_DISCONNECTED, "cannot calibrate '%s': %s", name(),
				exchange_.status().reason.c_str());
	}
	const HdApi &hd = library_.api();
	sync_error_ = HDErrorInfo{};
	hd.hdScheduleSynchronous(&HdDevice::recalibration_callback, this, HD_MAX_SCHEDULER_PRIORITY);
	if (hd_failed(sync_error_)) {
		return hd_status(StatusCode::DEVICE_ERROR, hd, "hdUpdateCalibration", sync_error_);
	}
	const HDenum status = calibration_status_.load(std::memory_order_acquire);
	if (status == HD_CALIBRATION_OK) {
		return Status::success();
	}
	if (status == HD_CALIBRATION_NEEDS_MANUAL_INPUT) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s", INKWELL_REASON);
	}
	return Status::error(StatusCode::DEVICE_ERROR, "OpenHaptics calibration did not complete (%s)",
			calibration_name(status));
}

DeviceStatus HdDevice::status() const {
	DeviceStatus status = exchange_.status();
	if (status.io == DeviceIo::OK && open_ && !ready_.load(std::memory_order_acquire)) {
		// Not a fault: the servo runs and holds zero force until the device is calibrated.
		const bool manual = calibration_status_.load(std::memory_order_acquire) == HD_CALIBRATION_NEEDS_MANUAL_INPUT;
		std::snprintf(status.reason, DEVICE_REASON_CAPACITY, "%s", manual ? INKWELL_REASON : CALIBRATING_REASON);
	}
	return status;
}

DeviceIo HdDevice::write_force(const ForceCommand &p_command) {
	if (!is_finite(p_command.force_n) || !is_finite(p_command.impact_n)) {
		non_finite_commands_.fetch_add(1, std::memory_order_relaxed);
		return ExchangedDevice::write_force(ForceCommand{});
	}
	return ExchangedDevice::write_force(p_command);
}

} // namespace haptics::openhaptics
