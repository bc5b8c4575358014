#include "devices/pid/pid_device.h"

#include <cmath>

namespace haptics::pid {

namespace {

Status check_range(const char *p_name, double p_value, double p_min, double p_max) {
	if (!std::isfinite(p_value) || !(p_value > p_min) || !(p_value <= p_max)) {
		return Status::error(std::isfinite(p_value) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
				"pid_device.%s must be in (%g, %g] (got %g)", p_name, p_min, p_max, p_value);
	}
	return Status::success();
}

} // namespace

Status validate_pid_device_config(const PidDeviceConfig &p_config) {
	struct Range {
		const char *name;
		double value, min, max;
	};
	const Range ranges[] = {
		{ "max_force_n", p_config.max_force_n, 0.0, 100.0 },
		{ "max_continuous_force_n", p_config.max_continuous_force_n, 0.0, 100.0 },
		{ "max_stiffness_n_per_m", p_config.max_stiffness_n_per_m, 0.0, 1e5 },
		{ "workspace_radius_m", p_config.workspace_radius_m, 0.0, 1.0 },
		{ "io_rate_hz", p_config.io_rate_hz, 0.0, 1000.0 },
		{ "restart_interval_s", p_config.restart_interval_s, 0.0, 30.0 },
	};
	for (const Range &range : ranges) {
		const Status status = check_range(range.name, range.value, range.min, range.max);
		if (!status) {
			return status;
		}
	}
	if (p_config.effect.block_load_attempts == 0 || p_config.max_input_reports_per_cycle == 0) {
		return Status::error(StatusCode::OUT_OF_RANGE, "pid_device: block_load_attempts and max_input_reports_per_cycle must be >= 1");
	}
	return Status::success();
}

PidDevice::PidDevice(std::unique_ptr<hid::HidTransport> p_transport, std::string p_name, const PidDeviceConfig &p_config) :
		transport_(std::move(p_transport)), name_(std::move(p_name)), config_(p_config) {}

PidDevice::~PidDevice() {
	close();
}

Status PidDevice::open_session() {
	std::vector<uint8_t> bytes;
	Status status = transport_->report_descriptor(bytes);
	if (!status) {
		return status;
	}
	// Tolerant: AJ's PID fragment alone closes one collection too many (docs/devices/hid-pid.md).
	hid::ReportDescriptor descriptor;
	status = hid::ReportDescriptor::parse(bytes, hid::ParseOptions{ false }, descriptor);
	if (status) {
		status = hid::JoystickInputLayout::find(descriptor, input_);
	}
	if (status) {
		status = PidLayout::build(std::move(descriptor), layout_);
	}
	if (!status) {
		return status;
	}
	if (config_.infinite_duration != InfiniteDurationChoice::AUTO) {
		layout_.infinite_duration = config_.infinite_duration == InfiniteDurationChoice::ALL_ONES ? InfiniteDuration::ALL_ONES
																								  : InfiniteDuration::LOGICAL_MAX;
	}
	mapping_ = PidForceMapping{ config_.max_force_n, !input_.has_y, config_.invert_force_x, config_.invert_force_y };
	status = initialize_device(*transport_, layout_, config_.device_gain);
	if (status) {
		last_force_ = PidForce{ mapping_.wheel ? PID_DIRECTION_PLUS_X : uint16_t{ 0 }, 0 };
		status = effect_.upload(*transport_, layout_, last_force_.direction, 0, config_.effect);
	}
	if (status && effect_.play(*transport_, 1) != DeviceIo::OK) {
		status = Status::error(StatusCode::DEVICE_ERROR, "PID Effect Operation Start failed: %s", transport_->last_error());
	}
	return status;
}

Status PidDevice::open() {
	if (open_) {
		return Status::success();
	}
	Status status = validate_pid_device_config(config_);
	if (!status) {
		return status;
	}
	status = transport_->open();
	if (status) {
		status = open_session();
	}
	if (!status) {
		effect_.forget();
		transport_->close();
		return Status::error(status.code(), "cannot open '%s': %s", name_.c_str(), status.message());
	}
	state_ = DeviceState{};
	exchange_.reset(state_);
	cycles_since_start_ = 0;
	restart_cycles_ = static_cast<uint64_t>(std::llround(config_.restart_interval_s * config_.io_rate_hz));
	stopped_cleanly_ = false;
	input_reports_.store(0, std::memory_order_relaxed);
	other_input_reports_.store(0, std::memory_order_relaxed);
	reports_sent_.store(0, std::memory_order_relaxed);
	bytes_sent_.store(0, std::memory_order_relaxed);
	status = io_thread_.start(*this, exchange_, DeviceIoThreadOptions{ config_.io_rate_hz, 45 });
	if (!status) {
		(void)effect_.erase(*transport_);
		transport_->close();
		return status;
	}
	open_ = true;
	return Status::success();
}

void PidDevice::close() {
	if (!open_) {
		return;
	}
	io_thread_.stop(); // Runs io_stop() (level 0, stop) unless the I/O had already failed.
	const DeviceIo io = exchange_.status().io;
	if (io == DeviceIo::DISCONNECTED) {
		effect_.forget(); // Gone with the device.
	} else if (stopped_cleanly_) {
		(void)effect_.free_block(*transport_);
	} else {
		// The I/O failed some other way, or io_stop could not finish: best effort.
		(void)effect_.update(*transport_, last_force_.direction, 0);
		(void)effect_.erase(*transport_);
	}
	transport_->close();
	open_ = false;
}

Status PidDevice::calibrate() {
	if (!open_) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", name_.c_str());
	}
	return Status::success(); // A stick's centre is mechanical: nothing to home.
}

DeviceCapabilities PidDevice::capabilities() const {
	DeviceCapabilities capabilities;
	const int32_t axes = open_ && !input_.has_y ? 1 : 2;
	capabilities.input_dof = axes;
	capabilities.output_dof = axes;
	capabilities.output = ForceOutput::DIRECTIONAL;
	capabilities.limits.max_force_n = config_.max_force_n;
	capabilities.limits.max_continuous_force_n = config_.max_continuous_force_n;
	capabilities.limits.max_stiffness_n_per_m = config_.max_stiffness_n_per_m;
	capabilities.limits.workspace_radius_m = config_.workspace_radius_m;
	capabilities.native_rate_hz = config_.io_rate_hz;
	capabilities.physical = true;
	capabilities.button_count = static_cast<int32_t>(input_.button_count);
	return capabilities;
}

PidDeviceCounters PidDevice::counters() const {
	PidDeviceCounters counters;
	counters.reports_sent = reports_sent_.load(std::memory_order_relaxed);
	counters.bytes_sent = bytes_sent_.load(std::memory_order_relaxed);
	counters.input_reports = input_reports_.load(std::memory_order_relaxed);
	counters.other_input_reports = other_input_reports_.load(std::memory_order_relaxed);
	return counters;
}

DeviceIo PidDevice::read_inputs(DeviceExchange &r_exchange) {
	uint8_t buffer[PID_MAX_REPORT_BYTES];
	bool fresh = false;
	for (uint32_t i = 0; i < config_.max_input_reports_per_cycle; ++i) {
		size_t length = 0;
		const DeviceIo io = transport_->read_input(buffer, length);
		if (io != DeviceIo::OK) {
			r_exchange.fail(io, "PID stick: reading input failed: %s", transport_->last_error());
			return io;
		}
		if (length == 0) {
			break;
		}
		hid::JoystickSample sample;
		if (!hid::decode_joystick_input(input_, std::span<const uint8_t>(buffer, length), sample)) {
			other_input_reports_.fetch_add(1, std::memory_order_relaxed);
			continue;
		}
		input_reports_.fetch_add(1, std::memory_order_relaxed);
		state_.position_m = Vec3{ sample.x, -sample.y, 0.0 } * config_.workspace_radius_m;
		state_.buttons = sample.buttons;
		fresh = true;
	}
	if (fresh) {
		r_exchange.publish_state(state_);
	}
	return DeviceIo::OK;
}

DeviceIo PidDevice::io_cycle(DeviceExchange &r_exchange, double p_dt_s) {
	(void)p_dt_s;
	const ForceCommand command = r_exchange.latest_command();
	const PidForce force = map_force(command.force_n, mapping_, last_force_.direction);
	const uint64_t sent_before = effect_.reports_sent();
	DeviceIo io = effect_.update(*transport_, force.direction, force.level);
	if (io == DeviceIo::OK) {
		last_force_ = force;
		if (++cycles_since_start_ >= restart_cycles_) {
			cycles_since_start_ = 0;
			io = effect_.play(*transport_, 1);
		}
	}
	reports_sent_.fetch_add(effect_.reports_sent() - sent_before, std::memory_order_relaxed);
	bytes_sent_.store(effect_.bytes_sent(), std::memory_order_relaxed);
	if (io != DeviceIo::OK) {
		// The status first, so the player hears of it at once; then the slow repair, if any.
		r_exchange.fail(io, "PID stick: force update failed: %s", transport_->last_error());
		if (transport_->clear_halt()) {
			r_exchange.fail(io, "PID stick: force update failed: %s", transport_->last_error());
		}
		return io;
	}
	return read_inputs(r_exchange);
}

void PidDevice::io_stop() {
	const uint64_t sent_before = effect_.reports_sent();
	stopped_cleanly_ = effect_.update(*transport_, last_force_.direction, 0) == DeviceIo::OK &&
			effect_.stop(*transport_) == DeviceIo::OK;
	if (stopped_cleanly_) {
		last_force_.level = 0;
	}
	reports_sent_.fetch_add(effect_.reports_sent() - sent_before, std::memory_order_relaxed);
	bytes_sent_.store(effect_.bytes_sent(), std::memory_order_relaxed);
}

} // namespace haptics::pid
