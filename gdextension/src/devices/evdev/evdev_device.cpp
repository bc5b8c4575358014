#include "devices/evdev/evdev_device.h"

#include "devices/device_config_limits.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace haptics::evdev {

namespace {

void copy_name(char *r_name, size_t p_capacity, const char *p_text) {
	std::snprintf(r_name, p_capacity, "%s", p_text);
}

} // namespace

Status validate_evdev_device_config(const EvdevDeviceConfig &p_config) {
	if (p_config.path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "evdev_device.path is empty (expected /dev/input/eventN)");
	}
	return check_device_config_limits("evdev_device", { p_config.max_force_n, p_config.max_continuous_force_n, p_config.max_stiffness_n_per_m, p_config.workspace_radius_m, p_config.rate_hz });
}

Status evdev_open_error(int p_error, const char *p_path) {
	const int error = p_error < 0 ? -p_error : p_error;
	if (error == EACCES || error == EPERM) {
		return Status::error(StatusCode::DEVICE_ERROR,
				"no permission for %s: install the udev rule (tools/udev, see README Devices) or add yourself to the 'input' group",
				p_path);
	}
	if (error == ENOENT || error == ENXIO || error == ENODEV) {
		return Status::error(StatusCode::NO_DEVICE, "%s is not present (%s): the device is unplugged or the path is stale",
				p_path, errno_name(error));
	}
	return Status::error(StatusCode::DEVICE_ERROR, "cannot open %s: %s (%s)", p_path, errno_text(error), errno_name(error));
}

EvdevDevice::EvdevDevice(std::shared_ptr<EvdevSyscalls> p_sys, EvdevDeviceConfig p_config) :
		sys_(std::move(p_sys)), config_(std::move(p_config)) {
	if (!config_.model.empty()) {
		copy_name(name_, sizeof(name_), config_.model.c_str());
	}
	mapping_.shape = config_.shape == EvdevShapeChoice::WHEEL ? EvdevShape::WHEEL : EvdevShape::JOYSTICK;
}

EvdevDevice::~EvdevDevice() {
	release();
}

Status EvdevDevice::open() {
	if (open_ && exchange_.status().io == DeviceIo::OK) {
		return Status::success();
	}
	release();
	if (!sys_) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "evdev device '%s': no syscall layer", config_.path.c_str());
	}
	const Status valid = validate_evdev_device_config(config_);
	if (!valid) {
		return valid;
	}
	const Status opened = open_node();
	if (!opened) {
		release();
		return opened;
	}
	exchange_.reset(state_from_input());
	report_interval_s_ = output_report_interval_s(config_.path, config_.sysfs_root);
	since_update_s_ = 0.0;
	since_play_s_ = 0.0;
	hold_s_ = 0.0;
	DeviceIoThreadOptions options;
	options.rate_hz = config_.rate_hz;
	const Status started = io_thread_.start(*this, exchange_, options);
	if (!started) {
		release();
		return started;
	}
	open_ = true;
	return Status::success();
}

Status EvdevDevice::open_node() {
	const char *path = config_.path.c_str();
	const int fd = sys_->open_device(path);
	if (fd < 0) {
		return evdev_open_error(fd, path);
	}
	fd_ = fd;
	if (config_.model.empty()) {
		char name[sizeof(name_)] = {};
		if (sys_->ioctl(fd_, evdev_eviocgname(sizeof(name) - 1), name) > 0 && name[0] != '\0') {
			copy_name(name_, sizeof(name_), name); // name[] stays terminated: len - 1 asked.
		}
	}
	Status status = query_ff_features(*sys_, fd_, path, features_);
	if (status) {
		status = choose_ff_output(features_, path, output_);
	}
	EvdevInputLayout layout;
	if (status) {
		status = read_layout(layout);
	}
	if (!status) {
		return status;
	}
	input_.configure(layout);
	mapping_ = FfForceMapping{ config_.max_force_n, mapping_.shape, config_.invert_force_x, config_.invert_force_y };
	if (output_ == EvdevOutput::RUMBLE) {
		return rumble_.start(*sys_, fd_, features_, path, config_.takeover.gain);
	}
	return effect_.start(*sys_, fd_, features_, path, config_.takeover);
}

Status EvdevDevice::read_layout(EvdevInputLayout &r_layout) {
	const char *path = config_.path.c_str();
	uint8_t abs_bits[EVDEV_ABS_BITS_BYTES] = {};
	int result = sys_->ioctl(fd_, evdev_eviocgbit(EVDEV_EV_ABS, sizeof(abs_bits)), abs_bits);
	if (result < 0) {
		return Status::error(result == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: EVIOCGBIT(EV_ABS) failed: %s (%s)", path, errno_text(result), errno_name(result));
	}
	const bool has_x = test_bit(abs_bits, sizeof(abs_bits), EVDEV_ABS_X);
	const bool has_y = test_bit(abs_bits, sizeof(abs_bits), EVDEV_ABS_Y);
	const bool has_wheel = test_bit(abs_bits, sizeof(abs_bits), EVDEV_ABS_WHEEL);
	bool wheel = config_.shape == EvdevShapeChoice::WHEEL;
	if (config_.shape == EvdevShapeChoice::AUTO) {
		wheel = has_wheel || (has_x && !has_y);
	}
	if (wheel && !has_wheel && !has_x) {
		return Status::error(StatusCode::UNSUPPORTED, "%s: a wheel needs ABS_WHEEL or ABS_X, the device has neither", path);
	}
	if (!wheel && !(has_x && has_y)) {
		return Status::error(StatusCode::UNSUPPORTED, "%s: a joystick needs ABS_X and ABS_Y, the device lacks %s", path,
				has_x ? "ABS_Y" : "ABS_X");
	}
	r_layout.x_code = wheel && has_wheel ? EVDEV_ABS_WHEEL : EVDEV_ABS_X;
	r_layout.has_y = !wheel;
	mapping_.shape = wheel ? EvdevShape::WHEEL : EvdevShape::JOYSTICK;

	const uint16_t codes[2] = { r_layout.x_code, r_layout.y_code };
	AbsRange *ranges[2] = { &r_layout.x_range, &r_layout.y_range };
	for (size_t i = 0; i < (r_layout.has_y ? 2u : 1u); ++i) {
		uint8_t info[INPUT_ABSINFO_SIZE] = {};
		result = sys_->ioctl(fd_, evdev_eviocgabs(codes[i]), info);
		if (result < 0) {
			return Status::error(result == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
					"%s: EVIOCGABS(0x%02x) failed: %s (%s)", path, codes[i], errno_text(result), errno_name(result));
		}
		*ranges[i] = decode_absinfo(info);
		const char *axis = codes[i] == EVDEV_ABS_WHEEL ? "ABS_WHEEL" : (codes[i] == EVDEV_ABS_X ? "ABS_X" : "ABS_Y");
		const Status valid = validate_abs_range(*ranges[i], axis, path);
		if (!valid) {
			return valid;
		}
	}

	uint8_t key_bits[EVDEV_KEY_BITS_BYTES] = {};
	result = sys_->ioctl(fd_, evdev_eviocgbit(EVDEV_EV_KEY, sizeof(key_bits)), key_bits);
	if (result < 0) {
		return Status::error(result == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: EVIOCGBIT(EV_KEY) failed: %s (%s)", path, errno_text(result), errno_name(result));
	}
	r_layout.buttons = button_map_from_key_bits(key_bits, sizeof(key_bits));
	return Status::success();
}

void EvdevDevice::release() {
	io_thread_.stop(); // Runs io_stop() (zero force) unless the thread failed.
	if (fd_ >= 0) {
		effect_.stop_and_erase(); // Errors ignored: an unplugged device has nothing to stop.
		rumble_.stop_and_erase();
		sys_->close(fd_);
		fd_ = -1;
	}
	open_ = false;
}

void EvdevDevice::close() {
	release();
}

Status EvdevDevice::calibrate() {
	return exchange_.ready_status(open_, name_);
}

DeviceCapabilities EvdevDevice::capabilities() const {
	DeviceCapabilities capabilities;
	const bool wheel = mapping_.shape == EvdevShape::WHEEL;
	capabilities.input_dof = wheel ? 1 : 2;
	capabilities.output_dof = output_ == EvdevOutput::RUMBLE ? 0 : (wheel ? 1 : 2);
	capabilities.output = output_ == EvdevOutput::RUMBLE ? ForceOutput::VIBRATION : ForceOutput::DIRECTIONAL;
	capabilities.limits = { config_.max_force_n, config_.max_continuous_force_n, config_.max_stiffness_n_per_m,
		config_.workspace_radius_m };
	capabilities.native_rate_hz = config_.rate_hz;
	capabilities.physical = true;
	capabilities.button_count = static_cast<int32_t>(input_.layout().buttons.count);
	return capabilities;
}

DeviceState EvdevDevice::state_from_input() const {
	DeviceState state;
	const double radius = config_.workspace_radius_m;
	state.position_m = Vec3(input_.x() * radius, input_.y() * radius, 0.0);
	state.buttons = input_.buttons();
	return state;
}

DeviceIo EvdevDevice::fail(DeviceExchange &r_exchange, int p_error, const char *p_doing) {
	const char *path = config_.path.c_str();
	if (p_error == -ENODEV) {
		r_exchange.fail(DeviceIo::DISCONNECTED, "%s was unplugged (ENODEV while %s)", path, p_doing);
		return DeviceIo::DISCONNECTED;
	}
	// Still reachable: leave it at rest now, not whenever the game gets to close().
	effect_.stop_and_erase();
	rumble_.stop_and_erase();
	r_exchange.fail(DeviceIo::FAILED, "%s: %s failed: %s (%s)", path, p_doing, errno_text(p_error), errno_name(p_error));
	return DeviceIo::FAILED;
}

DeviceIo EvdevDevice::io_cycle(DeviceExchange &r_exchange, double p_dt_s) {
	const ForceCommand command = r_exchange.latest_command();
	since_update_s_ += p_dt_s;
	if (output_ == EvdevOutput::RUMBLE) {
		const int rumbled = rumble_.render(p_dt_s);
		if (rumbled < 0) {
			return fail(r_exchange, rumbled, "updating the rumble");
		}
	} else {
		const FfConstantForce wanted = map_force_to_constant(command.force_n, mapping_);
		// A force that changes while the device drains waits; the newest is sent when it may
		// be, so the last command always reaches the device.
		if (since_update_s_ >= hold_s_ && !(wanted == effect_.current())) {
			const FfConstantForce before = effect_.current();
			const int updated = effect_.update(wanted);
			if (updated < 0) {
				return fail(r_exchange, updated, "updating the force");
			}
			hold_s_ = update_hold_s(before, wanted, report_interval_s_);
			since_update_s_ = 0.0;
		}
		since_play_s_ += p_dt_s;
		if (since_play_s_ >= CONSTANT_EFFECT_RENEW_S) {
			const int renewed = effect_.renew();
			if (renewed < 0) {
				return fail(r_exchange, renewed, "renewing the force");
			}
			since_play_s_ = 0.0;
		}
	}
	const int result = drain_input_events(*sys_, fd_, input_, read_buffer_);
	if (result < 0) {
		return fail(r_exchange, result, "reading the stick");
	}
	r_exchange.publish_state(state_from_input());
	return DeviceIo::OK;
}

void EvdevDevice::io_stop() {
	effect_.update(FfConstantForce{});
	rumble_.update(FfRumbleLevels{});
}

DeviceIo EvdevDevice::write_force(const ForceCommand &p_command) {
	if (open_ && output_ == EvdevOutput::RUMBLE) {
		rumble_.offer_impact(p_command.impact_n);
	}
	return ExchangedDevice::write_force(p_command);
}

} // namespace haptics::evdev
