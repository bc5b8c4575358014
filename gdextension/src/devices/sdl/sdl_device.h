#pragma once

// A force-feedback device driven through SDL 3's haptic API (docs/devices/sdl.md): a stick or
// wheel whose driver SDL reaches (Linux: the kernel's evdev node; Windows: DirectInput) renders
// the servo's force as one constant effect (sdl_effect.h); a pad with rumble only (Linux
// FF_RUMBLE, a haptic; on Windows an XInput or HIDAPI pad, a joystick SDL 3 rumbles through
// SDL_RumbleJoystick) renders the servo's impacts on its motors.
//
// Device space: x right, y up (away from the user), newtons. SDL's haptic API has no input, so
// this device reports no position (input_dof 0): the game reads the stick as a joypad. Limits
// are nominal as for evdev: SDL's level 0x7FFF is "the device's strongest", max_force_n.
//
// I/O runs on a DeviceIoThread at rate_hz (250 Hz: an update is at most two reports on a PID
// device, whose interrupt endpoint takes one a millisecond; SDL says nothing of the endpoint,
// so the evdev backend's pacing cannot be had here). Each cycle, with the runtime's mutex
// held, it takes the newest servo force, updates the effect when its quantised (direction,
// level) changed, and runs the effect again every SDL_EFFECT_RENEW_S. SDL reports failures
// as text: one whose text says the device is gone (on Linux strerror(ENODEV), "No such
// device") makes the device DISCONNECTED, any other FAILED, each with SDL's text. close() and
// errors leave the device at zero force with its effect stopped and destroyed where it can.
// A joystick's rumble has no effect to renew: SDL_RumbleJoystick is sent when the levels change
// and again every SDL_EFFECT_RENEW_S with SDL_EFFECT_LENGTH_MS (SDL stops it after that length
// when its joysticks are updated, which the I/O thread does at the same renewal); a joystick
// SDL no longer has connected makes the device DISCONNECTED.
//
// Gain and autocentre: SDL_OpenHaptic sets the gain to 100 and the autocentre to 0 itself
// (SDL_haptic.c), so through SDL the game always takes the gain, whatever
// HapticDeviceOpenOptions.take_gain says (the docs say so), and the centring spring is off;
// a game that asks to keep the spring (spring_off false) has it set back to full
// (SDL_SetHapticAutocenter 100), hid-pidff's own setting when it binds a device.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"
#include "devices/exchanged_device.h"
#include "devices/sdl/sdl_effect.h"
#include "devices/sdl/sdl_runtime.h"

#include <atomic>
#include <string>

namespace haptics::sdl {

enum class SdlOutput : int32_t {
	CONSTANT = 0, // SDL_HAPTIC_CONSTANT: the force.
	LEFTRIGHT = 1, // SDL_HAPTIC_LEFTRIGHT: two motors for the impacts.
	SIMPLE_RUMBLE = 2, // SDL_InitHapticRumble / SDL_PlayHapticRumble: one strength.
	JOYSTICK_RUMBLE = 3, // SDL_RumbleJoystick: a joystick's two motors, no haptic.
};

// CONSTANT when SDL offers a constant force, else LEFTRIGHT, else the simple rumble where SDL
// can make one (a sine); UNSUPPORTED "SDL offers neither constant force nor rumble on this
// device (<features>)" otherwise.
Status choose_sdl_output(uint32_t p_features, const std::string &p_described, SdlOutput &r_output);

struct SdlDeviceConfig {
	std::string key; // SdlHapticEntry::key.
	std::string model; // name(); empty = SDL's name.
	double max_force_n = 5.0; // Sent as level 0x7FFF. (0, 100]
	double max_continuous_force_n = 2.5; // (0, max_force_n]
	double max_stiffness_n_per_m = 300.0; // (0, 1e5]
	double workspace_radius_m = 0.05; // (0, 1]
	double rate_hz = 250.0; // (0, 1000]
	bool invert_force_x = false;
	bool invert_force_y = false;
	bool keep_spring = false; // HapticDeviceOpenOptions.spring_off == false.
};

// Ranges above; the message names the field.
Status validate_sdl_device_config(const SdlDeviceConfig &p_config);

class SdlHapticDevice final : public ExchangedDevice, private DeviceIoWorker {
public:
	// p_runtime must outlive the device.
	SdlHapticDevice(SdlRuntime &r_runtime, SdlDeviceConfig p_config);
	~SdlHapticDevice() override;

	// Opens what the runtime's last listing named config().key (a haptic or a joystick), creates
	// and runs the effect, starts the I/O thread. Idempotent while healthy; after a failure opens afresh.
	Status open() override;
	void close() override;
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override { return name_; }
	// A rumble device takes the transients' peak here, every tick (an atomic max).
	DeviceIo write_force(const ForceCommand &p_command) override;

	SdlOutput output() const { return output_; }
	uint32_t features() const { return features_; }
	int32_t axes() const { return axes_; }
	const SdlDeviceConfig &config() const { return config_; }

private:
	DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) override;
	void io_stop() override;

	Status start_effect();
	bool send_constant(const SdlConstantForce &p_force);
	bool send_rumble(const SdlRumbleLevels &p_levels, double p_strength);
	bool unplugged(const char *p_text) const;
	DeviceIo fail(DeviceExchange &r_exchange, const char *p_doing);
	void release();

	SdlRuntime &runtime_;
	SdlDeviceConfig config_;
	char name_[128] = "SDL haptic device";
	SdlOpened opened_; // Its haptic, or its joystick (JOYSTICK_RUMBLE).
	uint32_t features_ = 0;
	int32_t axes_ = 0;
	SdlOutput output_ = SdlOutput::CONSTANT;
	SdlForceMapping mapping_;
	SdlEffectId effect_id_ = -1;
	SdlConstantForce constant_;
	SdlRumbleLevels rumble_;
	double strength_ = 0.0; // The simple rumble's.
	SdlRumbleMapping rumble_mapping_;
	SdlRumbleEnvelope envelope_;
	std::atomic<double> peak_n_{ 0.0 };
	double since_run_s_ = 0.0;
	DeviceIoThread io_thread_;
};

} // namespace haptics::sdl
