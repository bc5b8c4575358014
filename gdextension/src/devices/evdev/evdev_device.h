#pragma once

// A force-feedback joystick or wheel driven through /dev/input/eventN: the path most Linux
// FFB devices take, because the kernel's hid-pidff or vendor driver owns the HID device
// and offers force feedback there (docs/devices/evdev.md). One FF_CONSTANT effect carries the servo's
// force (evdev_effect.h); the stick is the input (evdev_input.h).
//
// Device space: x right, y up (away from the user), metres; position_m = deflection x
// workspace_radius_m, so the input vector IS the deflection. Velocity is not measured
// (zero). A wheel reads ABS_WHEEL (or ABS_X) into x and renders x only.
//
// Nominal limits (the kernel API has no unit: level 0x7FFF is "full"): max_force_n is the
// force sent as full level; 5 N is the order of a PID stick's grip force. The continuous
// rating defaults to half of it because hobby FFB motors and H-bridges are not rated for
// sustained full torque. Stiffness 300 N/m over a 5 cm "radius" reaches full force at
// a third of the travel: stable at a 500 Hz update with a few ms of USB latency.
//
// I/O runs on a DeviceIoThread at rate_hz (500 Hz default). Each cycle takes the newest servo
// force, uploads it if its quantised (direction, level) changed and the device has drained
// the previous update (evdev_pacing.h: the kernel drops what outruns the endpoint, silently),
// drains the input events and publishes the state. An unplugged device (ENODEV) becomes
// DISCONNECTED with a reason; any other errno FAILED with strerror. close() and errors
// leave the device at zero force, stopped, with the effect erased where it is reachable.
//
// A node whose driver offers rumble but no FF_CONSTANT (a gamepad) opens as a vibration
// device: the same sequence with one FF_RUMBLE effect rendering the servo's impacts
// (evdev_rumble.h); output VIBRATION, no force axes.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"
#include "devices/evdev/evdev_effect.h"
#include "devices/evdev/evdev_input.h"
#include "devices/evdev/evdev_pacing.h"
#include "devices/evdev/evdev_rumble.h"
#include "devices/evdev/evdev_syscalls.h"
#include "devices/exchanged_device.h"

#include <memory>
#include <string>

namespace haptics::evdev {

enum class EvdevShapeChoice : int32_t {
	AUTO = 0, // ABS_WHEEL, or ABS_X without ABS_Y -> wheel; else joystick.
	JOYSTICK = 1,
	WHEEL = 2, // For wheels whose pedals sit on ABS_Y (a catalog entry knows).
};

struct EvdevDeviceConfig {
	std::string path; // /dev/input/eventN
	std::string model; // name(); empty = the kernel's EVIOCGNAME.
	EvdevShapeChoice shape = EvdevShapeChoice::AUTO;
	double max_force_n = 5.0; // Sent as level 0x7FFF. (0, 100]
	double max_continuous_force_n = 2.5; // (0, max_force_n]
	double max_stiffness_n_per_m = 300.0; // (0, 1e5]
	double workspace_radius_m = 0.05; // Full deflection, (0, 1]
	double rate_hz = 500.0; // (0, 1000]
	// The physical sign of a direction needs one hardware check per device family (see
	// evdev_ff.h); these flip the force, never the input.
	bool invert_force_x = false;
	bool invert_force_y = false;
	// What the game lets the start change on the device (its gain, its centring spring).
	EvdevTakeover takeover;
	std::string sysfs_root = "/sys"; // Where the endpoint's interval is read; tests fake it.
};

// Ranges above; the message names the field.
Status validate_evdev_device_config(const EvdevDeviceConfig &p_config);

// What a failed open(2) of p_path means for the player: EACCES/EPERM -> the udev rule or
// the 'input' group (DEVICE_ERROR); ENOENT/ENXIO/ENODEV -> not present (NO_DEVICE); else
// strerror (DEVICE_ERROR). p_error may be negative.
Status evdev_open_error(int p_error, const char *p_path);

class EvdevDevice final : public ExchangedDevice, private DeviceIoWorker {
public:
	EvdevDevice(std::shared_ptr<EvdevSyscalls> p_sys, EvdevDeviceConfig p_config);
	~EvdevDevice() override;

	// Opens the node, checks FF_CONSTANT, reads the axes, starts the effect (evdev_effect.h)
	// and the I/O thread. Idempotent while healthy; after an I/O failure (unplugged) it
	// closes and opens afresh.
	Status open() override;
	void close() override;
	// Joysticks and wheels centre themselves (springs, or the driver's calibration): nothing
	// to do but check the device is open.
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override { return name_; }
	// A vibration device hands the transients' peak to the I/O thread, every tick.
	DeviceIo write_force(const ForceCommand &p_command) override;

	EvdevShape shape() const { return mapping_.shape; }
	const EvdevDeviceConfig &config() const { return config_; }
	// What the kernel offered at open, and what renders the servo.
	const EvdevFfFeatures &features() const { return features_; }
	EvdevOutput output() const { return output_; }

private:
	DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) override;
	void io_stop() override;

	Status open_node();
	Status read_layout(EvdevInputLayout &r_layout);
	DeviceState state_from_input() const;
	DeviceIo fail(DeviceExchange &r_exchange, int p_error, const char *p_doing);
	void release();

	std::shared_ptr<EvdevSyscalls> sys_;
	EvdevDeviceConfig config_;
	char name_[128] = "evdev force-feedback device";
	int fd_ = -1;
	EvdevFfFeatures features_;
	EvdevOutput output_ = EvdevOutput::CONSTANT;
	FfForceMapping mapping_;
	EvdevConstantForce effect_;
	double report_interval_s_ = 0.0; // Of the interrupt OUT endpoint, read at open.
	double since_update_s_ = 0.0;
	double hold_s_ = 0.0; // Until the device has drained the last update.
	double since_play_s_ = 0.0; // Since the constant force was last played (renewed).
	EvdevRumble rumble_;
	EvdevInputDecoder input_;
	uint8_t read_buffer_[INPUT_READ_BUFFER_SIZE] = {};
	DeviceIoThread io_thread_;
};

} // namespace haptics::evdev
