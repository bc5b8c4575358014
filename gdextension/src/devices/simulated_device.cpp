#include "devices/simulated_device.h"

#include "devices/device_info.h"

#include <cmath>
#include <cstdio>

namespace haptics {

namespace {

Status check_range(const char *p_name, double p_value, double p_min, double p_max, bool p_min_exclusive) {
	const bool below = p_min_exclusive ? !(p_value > p_min) : !(p_value >= p_min);
	if (!std::isfinite(p_value) || below || !(p_value <= p_max)) {
		return Status::error(std::isfinite(p_value) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
				"simulated_device.%s must be in %s%g, %g] (got %g)", p_name, p_min_exclusive ? "(" : "[", p_min, p_max,
				p_value);
	}
	return Status::success();
}

} // namespace

Status validate_simulated_device_config(const SimulatedDeviceConfig &p_config) {
	struct Field {
		const char *name;
		double value, min, max;
		bool min_exclusive;
	};
	const Field fields[] = {
		{ "workspace_radius_m", p_config.workspace_radius_m, 0.0, 1.0, true },
		{ "max_force_n", p_config.max_force_n, 0.0, 100.0, true },
		{ "max_continuous_force_n", p_config.max_continuous_force_n, 0.0, 100.0, true },
		{ "max_stiffness_n_per_m", p_config.max_stiffness_n_per_m, 0.0, 1e5, true },
		{ "stylus_mass_kg", p_config.stylus_mass_kg, 0.0, 10.0, true },
		{ "hand_stiffness_n_per_m", p_config.hand_stiffness_n_per_m, 0.0, 1e5, false },
		{ "hand_damping_n_s_per_m", p_config.hand_damping_n_s_per_m, 0.0, 1e4, false },
	};
	for (const Field &field : fields) {
		const Status status = check_range(field.name, field.value, field.min, field.max, field.min_exclusive);
		if (!status) {
			return status;
		}
	}
	return Status::success();
}

SimulatedDevice::SimulatedDevice(const SimulatedDeviceConfig &p_config) :
		config_(p_config) {}

Status SimulatedDevice::open() {
	if (!plugged()) {
		return Status::error(StatusCode::DEVICE_DISCONNECTED, "cannot open '%s': device unplugged", name());
	}
	const Status valid = validate_simulated_device_config(config_);
	if (!valid) {
		return valid;
	}
	// Start at rest where the hand is, so opening never makes the stylus jump.
	target_ = hand_target_.load();
	position_ = clamp_to_workspace(target_);
	velocity_ = Vec3{};
	force_ = Vec3{};
	open_ = true;
	return Status::success();
}

void SimulatedDevice::close() {
	force_ = Vec3{};
	open_ = false;
}

Status SimulatedDevice::calibrate() {
	if (!open_) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", name());
	}
	if (!plugged()) {
		return Status::error(StatusCode::DEVICE_DISCONNECTED, "cannot calibrate '%s': device unplugged", name());
	}
	return Status::success(); // A simulation is always calibrated.
}

DeviceCapabilities SimulatedDevice::capabilities() const {
	DeviceCapabilities capabilities;
	capabilities.input_dof = 3;
	capabilities.output_dof = 3;
	capabilities.output = ForceOutput::DIRECTIONAL;
	capabilities.limits = { config_.max_force_n, config_.max_continuous_force_n, config_.max_stiffness_n_per_m,
		config_.workspace_radius_m };
	capabilities.physical = false; // No hand to kick: tests and the game start forces at once.
	capabilities.button_count = 32;
	return capabilities;
}

DeviceStatus SimulatedDevice::status() const {
	DeviceStatus status;
	if (!plugged()) {
		status.io = DeviceIo::DISCONNECTED;
		std::snprintf(status.reason, DEVICE_REASON_CAPACITY, "simulated cable pulled");
	}
	return status;
}

const char *SimulatedDevice::name() const {
	return SIMULATED_DEVICE_MODEL.data(); // A string literal: null-terminated.
}

Status SimulatedDevice::set_hand_target(const Vec3 &p_target_m) {
	if (!is_finite(p_target_m)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "hand_target: not finite (%g, %g, %g)", p_target_m.x,
				p_target_m.y, p_target_m.z);
	}
	if (length(p_target_m) > 1.0) {
		return Status::error(StatusCode::OUT_OF_RANGE, "hand_target: |target| must be <= 1 m (got %g m)",
				length(p_target_m));
	}
	hand_target_.store(p_target_m);
	return Status::success();
}

Vec3 SimulatedDevice::clamp_to_workspace(const Vec3 &p_position) const {
	const double distance = length(p_position);
	return distance > config_.workspace_radius_m ? p_position * (config_.workspace_radius_m / distance) : p_position;
}

void SimulatedDevice::begin_tick(double p_dt_s) {
	if (!open_ || !plugged()) {
		return;
	}
	Vec3 target;
	if (hand_target_.try_load(target)) {
		target_ = target; // Else keep the previous target: the game is mid-update.
	}
	if (config_.rigid_hand) {
		const Vec3 next = clamp_to_workspace(target_);
		velocity_ = (next - position_) / p_dt_s;
		position_ = next;
		return;
	}
	const double m = config_.stylus_mass_kg;
	const double k = config_.hand_stiffness_n_per_m;
	const double b = config_.hand_damping_n_s_per_m;
	const double dt = p_dt_s;
	// Backward Euler on m v' = F + k (target - x) - b v, x' = v, with F held over the tick.
	velocity_ = (velocity_ * m + (force_ + (target_ - position_) * k) * dt) / (m + dt * b + dt * dt * k);
	position_ += velocity_ * dt;

	// Inelastic end stops: back onto the sphere, outward velocity removed.
	const double distance = length(position_);
	if (distance > config_.workspace_radius_m) {
		const Vec3 outward = position_ / distance;
		position_ = outward * config_.workspace_radius_m;
		const double radial_speed = dot(velocity_, outward);
		if (radial_speed > 0.0) {
			velocity_ -= outward * radial_speed;
		}
	}
}

DeviceIo SimulatedDevice::read_state(DeviceState &r_state) {
	if (!plugged()) {
		return DeviceIo::DISCONNECTED;
	}
	if (!open_) {
		return DeviceIo::FAILED;
	}
	r_state.position_m = position_;
	r_state.velocity_m_per_s = velocity_;
	r_state.buttons = buttons_.load(std::memory_order_relaxed);
	return DeviceIo::OK;
}

DeviceIo SimulatedDevice::write_force(const ForceCommand &p_command) {
	if (!plugged()) {
		return DeviceIo::DISCONNECTED;
	}
	if (!open_) {
		return DeviceIo::FAILED;
	}
	force_ = p_command.force_n;
	return DeviceIo::OK;
}

} // namespace haptics
