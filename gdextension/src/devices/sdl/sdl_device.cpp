#include "devices/sdl/sdl_device.h"

#include "devices/device_config_limits.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace haptics::sdl {

namespace {

// The two motors' 0..0x7FFF as SDL_RumbleJoystick's 0..0xFFFF, doubled as SDL's Linux haptic
// driver doubles them for FF_RUMBLE, so a level means the same strength on both paths.
Uint16 joystick_motor(uint16_t p_level) {
	return static_cast<Uint16>(std::min<uint32_t>(p_level * 2u, 0xffffu));
}

} // namespace

Status choose_sdl_output(uint32_t p_features, const std::string &p_described, SdlOutput &r_output) {
	if ((p_features & SDL_HAPTIC_CONSTANT) != 0) {
		r_output = SdlOutput::CONSTANT;
	} else if ((p_features & SDL_HAPTIC_LEFTRIGHT) != 0) {
		r_output = SdlOutput::LEFTRIGHT;
	} else if ((p_features & SDL_HAPTIC_SINE) != 0) {
		r_output = SdlOutput::SIMPLE_RUMBLE;
	} else {
		return Status::error(StatusCode::UNSUPPORTED, "SDL offers neither constant force nor rumble on this device (%s)",
				p_described.c_str());
	}
	return Status::success();
}

Status validate_sdl_device_config(const SdlDeviceConfig &p_config) {
	if (p_config.key.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "sdl_device.key is empty (expected '<name>#<k>' from a listing)");
	}
	return check_device_config_limits("sdl_device", { p_config.max_force_n, p_config.max_continuous_force_n, p_config.max_stiffness_n_per_m, p_config.workspace_radius_m, p_config.rate_hz });
}

SdlHapticDevice::SdlHapticDevice(SdlRuntime &r_runtime, SdlDeviceConfig p_config) :
		runtime_(r_runtime), config_(std::move(p_config)) {
	std::snprintf(name_, sizeof(name_), "%s", config_.model.empty() ? config_.key.c_str() : config_.model.c_str());
}

SdlHapticDevice::~SdlHapticDevice() {
	release();
}

Status SdlHapticDevice::open() {
	if (open_ && exchange_.status().io == DeviceIo::OK) {
		return Status::success();
	}
	release();
	const Status valid = validate_sdl_device_config(config_);
	if (!valid) {
		return valid;
	}
	{
		std::lock_guard lock(runtime_.mutex());
		std::string error;
		if (!runtime_.open(config_.key, opened_, error)) {
			return Status::error(StatusCode::NO_DEVICE, "SDL cannot open '%s': %s", config_.key.c_str(), error.c_str());
		}
		const Status started = start_effect();
		if (!started) {
			runtime_.close(opened_);
			return started;
		}
	}
	exchange_.reset(DeviceState{});
	since_run_s_ = 0.0;
	envelope_.reset();
	peak_n_.store(0.0, std::memory_order_relaxed);
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

// With the runtime's mutex held.
Status SdlHapticDevice::start_effect() {
	const SdlApi &api = runtime_.api();
	rumble_ = SdlRumbleLevels{};
	strength_ = 0.0;
	if (opened_.joystick != nullptr) {
		output_ = SdlOutput::JOYSTICK_RUMBLE;
		features_ = 0;
		axes_ = 0;
		return Status::success();
	}
	features_ = api.GetHapticFeatures(opened_.haptic);
	axes_ = api.GetNumHapticAxes(opened_.haptic);
	SdlHapticEntry described;
	described.features_read = true;
	described.features = features_;
	described.axes = axes_;
	described.max_effects = api.GetMaxHapticEffects(opened_.haptic);
	const Status chosen = choose_sdl_output(features_, describe_sdl_features(described), output_);
	if (!chosen) {
		return chosen;
	}
	if (config_.keep_spring && (features_ & SDL_HAPTIC_AUTOCENTER) != 0 && !api.SetHapticAutocenter(opened_.haptic, 100)) {
		return Status::error(StatusCode::DEVICE_ERROR, "SDL could not keep the centring spring of '%s': %s", name_,
				runtime_.error_text());
	}
	mapping_ = SdlForceMapping{ config_.max_force_n, axes_ == 1, config_.invert_force_x, config_.invert_force_y };
	constant_ = SdlConstantForce{};
	constant_.direction_type = mapping_.steering ? SDL_HAPTIC_STEERING_AXIS : SDL_HAPTIC_POLAR;
	if (output_ == SdlOutput::SIMPLE_RUMBLE) {
		if (!api.InitHapticRumble(opened_.haptic)) {
			return Status::error(StatusCode::DEVICE_ERROR, "SDL could not start the rumble of '%s': %s", name_, runtime_.error_text());
		}
		return Status::success();
	}
	const SDL_HapticEffect effect = output_ == SdlOutput::CONSTANT ? constant_effect(constant_) : leftright_effect(rumble_);
	effect_id_ = api.CreateHapticEffect(opened_.haptic, &effect);
	if (effect_id_ < 0) {
		return Status::error(StatusCode::DEVICE_ERROR, "SDL could not upload the %s effect to '%s': %s",
				output_ == SdlOutput::CONSTANT ? "constant-force" : "rumble", name_, runtime_.error_text());
	}
	if (!api.RunHapticEffect(opened_.haptic, effect_id_, 1)) {
		const Status failed = Status::error(StatusCode::DEVICE_ERROR, "SDL could not play the effect on '%s': %s", name_,
				runtime_.error_text());
		api.DestroyHapticEffect(opened_.haptic, effect_id_);
		effect_id_ = -1;
		return failed;
	}
	return Status::success();
}

bool SdlHapticDevice::send_constant(const SdlConstantForce &p_force) {
	const SDL_HapticEffect effect = constant_effect(p_force);
	if (!runtime_.api().UpdateHapticEffect(opened_.haptic, effect_id_, &effect)) {
		return false;
	}
	constant_ = p_force;
	return true;
}

bool SdlHapticDevice::send_rumble(const SdlRumbleLevels &p_levels, double p_strength) {
	const SdlApi &api = runtime_.api();
	if (output_ == SdlOutput::JOYSTICK_RUMBLE) {
		if (!api.RumbleJoystick(opened_.joystick, joystick_motor(p_levels.large), joystick_motor(p_levels.small),
					SDL_EFFECT_LENGTH_MS)) {
			return false;
		}
		rumble_ = p_levels;
		return true;
	}
	if (output_ == SdlOutput::LEFTRIGHT) {
		const SDL_HapticEffect effect = leftright_effect(p_levels);
		if (!api.UpdateHapticEffect(opened_.haptic, effect_id_, &effect)) {
			return false;
		}
		rumble_ = p_levels;
		return true;
	}
	const bool sent = p_strength > 0.0
			? api.PlayHapticRumble(opened_.haptic, static_cast<float>(p_strength), SDL_EFFECT_LENGTH_MS)
			: api.StopHapticRumble(opened_.haptic);
	if (sent) {
		strength_ = p_strength;
	}
	return sent;
}

// SDL reports failures as text only; its Linux driver appends strerror(errno), so an unplugged
// device's calls end in strerror(ENODEV). A joystick SDL has seen go is no longer connected.
bool SdlHapticDevice::unplugged(const char *p_text) const {
	if (opened_.joystick != nullptr && !runtime_.api().JoystickConnected(opened_.joystick)) {
		return true;
	}
	return std::strstr(p_text, std::strerror(ENODEV)) != nullptr;
}

DeviceIo SdlHapticDevice::fail(DeviceExchange &r_exchange, const char *p_doing) {
	const char *text = runtime_.error_text();
	if (unplugged(text)) {
		r_exchange.fail(DeviceIo::DISCONNECTED, "%s was unplugged (SDL, while %s: %s)", name_, p_doing, text);
		return DeviceIo::DISCONNECTED;
	}
	r_exchange.fail(DeviceIo::FAILED, "%s: SDL failed %s: %s", name_, p_doing, text);
	return DeviceIo::FAILED;
}

DeviceIo SdlHapticDevice::io_cycle(DeviceExchange &r_exchange, double p_dt_s) {
	const ForceCommand command = r_exchange.latest_command();
	std::lock_guard lock(runtime_.mutex());
	since_run_s_ += p_dt_s;
	const bool renew = since_run_s_ >= SDL_EFFECT_RENEW_S;
	if (output_ == SdlOutput::CONSTANT) {
		const SdlConstantForce wanted = map_force_to_sdl(command.force_n, mapping_);
		if (!(wanted == constant_) && !send_constant(wanted)) {
			return fail(r_exchange, "updating the force");
		}
	} else {
		const double peak = peak_n_.exchange(0.0, std::memory_order_relaxed);
		const SdlRumbleLevels levels = envelope_.update(peak, p_dt_s, rumble_mapping_);
		const double strength = envelope_.level();
		const bool changed = output_ == SdlOutput::SIMPLE_RUMBLE ? strength != strength_ : !(levels == rumble_);
		// The simple rumble and a joystick's have no effect of ours to run again: sending them
		// again renews them.
		const bool replay = output_ != SdlOutput::LEFTRIGHT && renew && strength > 0.0;
		if ((changed || replay) && !send_rumble(levels, strength)) {
			return fail(r_exchange, "updating the rumble");
		}
	}
	if (renew && opened_.joystick != nullptr) {
		// SDL notices a joystick gone, and ends a rumble past its length, when it updates them.
		runtime_.api().UpdateJoysticks();
		if (!runtime_.api().JoystickConnected(opened_.joystick)) {
			return fail(r_exchange, "renewing the rumble");
		}
	}
	if (renew) {
		if (effect_id_ >= 0 && !runtime_.api().RunHapticEffect(opened_.haptic, effect_id_, 1)) {
			return fail(r_exchange, "renewing the effect");
		}
		since_run_s_ = 0.0;
	}
	r_exchange.publish_state(DeviceState{});
	return DeviceIo::OK;
}

void SdlHapticDevice::io_stop() {
	std::lock_guard lock(runtime_.mutex());
	if (output_ == SdlOutput::CONSTANT) {
		(void)send_constant(SdlConstantForce{ constant_.direction_type, 0, 0 });
	} else {
		(void)send_rumble(SdlRumbleLevels{}, 0.0);
	}
}

void SdlHapticDevice::release() {
	io_thread_.stop(); // Runs io_stop() (zero) unless the thread failed.
	std::lock_guard lock(runtime_.mutex());
	const SdlApi &api = runtime_.api();
	// Errors ignored: an unplugged device has nothing left to stop.
	if (opened_.haptic != nullptr) {
		if (effect_id_ >= 0) {
			(void)api.StopHapticEffect(opened_.haptic, effect_id_);
			api.DestroyHapticEffect(opened_.haptic, effect_id_);
		} else if (output_ == SdlOutput::SIMPLE_RUMBLE) {
			(void)api.StopHapticRumble(opened_.haptic);
		}
	} else if (opened_.joystick != nullptr) {
		(void)api.RumbleJoystick(opened_.joystick, 0, 0, 0);
	}
	runtime_.close(opened_);
	effect_id_ = -1;
	open_ = false;
}

void SdlHapticDevice::close() {
	release();
}

Status SdlHapticDevice::calibrate() {
	return exchange_.ready_status(open_, name_);
}

DeviceCapabilities SdlHapticDevice::capabilities() const {
	DeviceCapabilities capabilities;
	const bool force = output_ == SdlOutput::CONSTANT;
	capabilities.input_dof = 0;
	capabilities.output_dof = force ? (mapping_.steering ? 1 : 2) : 0;
	capabilities.output = force ? ForceOutput::DIRECTIONAL : ForceOutput::VIBRATION;
	capabilities.limits = { config_.max_force_n, config_.max_continuous_force_n, config_.max_stiffness_n_per_m,
		config_.workspace_radius_m };
	capabilities.native_rate_hz = config_.rate_hz;
	capabilities.physical = true;
	return capabilities;
}

DeviceIo SdlHapticDevice::write_force(const ForceCommand &p_command) {
	if (open_ && output_ != SdlOutput::CONSTANT) {
		const double magnitude = length(p_command.impact_n);
		double peak = peak_n_.load(std::memory_order_relaxed);
		while (std::isfinite(magnitude) && magnitude > peak &&
				!peak_n_.compare_exchange_weak(peak, magnitude, std::memory_order_relaxed)) {
		}
	}
	return ExchangedDevice::write_force(p_command);
}

} // namespace haptics::sdl
