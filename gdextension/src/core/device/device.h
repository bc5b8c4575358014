#pragma once

// The device interface every backend implements (CHAI3D's cGenericHapticDevice, reduced to
// what our renderers need). Device space: x right, y up, z toward the user, metres, newtons
// (coordinates.h). Each backend maps its own axes onto these and says how in its header.
//
// Threading contract, which the engine upholds:
//  - open, close, calibrate, capabilities, name, status, set_hand_target: the game
//    thread; open/close/calibrate never while the servo is running.
//  - begin_tick, read_state, write_force: the servo thread (or the caller of step()), one
//    at a time. They must not allocate, lock a mutex that a non-real-time thread can hold,
//    log, or wait on a bus: a device whose I/O is slower than the servo runs that I/O on its
//    own thread and exchanges the latest state and force with the servo lock-free
//    (device_exchange.h), so the tick only copies.
//  - A device that disappears (unplugged) reports DeviceIo::DISCONNECTED from the servo
//    calls; the servo then writes zero, stops rendering, and the engine reports status().

#include "core/base/status.h"
#include "core/base/vec3.h"
#include "core/device/software_cable.h"

#include <cstdint>

namespace haptics {

struct DeviceLimits {
	double max_force_n = 0.0; // Peak force the device may be commanded (transients), N.
	double max_continuous_force_n = 0.0; // Sustainable force: the default continuous cap, N.
	double max_stiffness_n_per_m = 0.0; // Highest stable virtual stiffness, N/m.
	double workspace_radius_m = 0.0; // Radius of the usable workspace sphere, m.
};

// What the device can feel and render. Directional devices push the hand; vibration-only
// devices (a gamepad) render transients as rumble and the continuous force's magnitude as
// something it can (the DualSense's trigger resistance).
enum class ForceOutput : int32_t {
	NONE = 0,
	DIRECTIONAL = 1,
	VIBRATION = 2,
};

struct DeviceCapabilities {
	int32_t input_dof = 3; // Position axes read: 1 wheel, 2 joystick, 3 Falcon/Touch.
	int32_t output_dof = 3; // Force axes rendered (0 when output is VIBRATION or NONE).
	ForceOutput output = ForceOutput::DIRECTIONAL;
	DeviceLimits limits;
	double native_rate_hz = 0.0; // The rate the device's own I/O runs at; 0 = the servo's.
	bool has_orientation = false; // DeviceState::orientation is meaningful (Touch gimbal).
	bool needs_homing = false; // No force until DeviceState::ready (Falcon homing).
	// A physical device: the servo holds zero force at start until the rendered force is
	// small (SafetyConfig::start_force_n), so a session never starts by kicking the hand.
	bool physical = true;
	int32_t button_count = 0;
};

// A rotation as a unit quaternion (w, x, y, z), device space. Identity when the device has
// no orientation.
struct Orientation {
	double w = 1.0;
	double x = 0.0;
	double y = 0.0;
	double z = 0.0;
};

struct DeviceState {
	Vec3 position_m; // Stylus tip or stick deflection scaled to the workspace, centred.
	Vec3 velocity_m_per_s; // Zero where the device does not measure or estimate it.
	Orientation orientation;
	uint32_t buttons = 0; // Bit b set when button b is pressed.
	// False while the device is not yet homed/calibrated: the servo writes zero force.
	bool ready = true;
};

// What the servo hands the device each tick, after safety.
struct ForceCommand {
	Vec3 force_n; // Total force: continuous plus transients. Directional devices render it.
	Vec3 impact_n; // The transients' share of force_n (rumble on vibration-only devices).
};

enum class DeviceIo : int32_t {
	OK = 0,
	DISCONNECTED = 1,
	FAILED = 2, // Any other I/O failure; rendering stops too.
};

// The device's health as the game shows it. `reason` is empty when OK, else one sentence
// for the player, e.g. "USB transfer failed: LIBUSB_ERROR_NO_DEVICE".
struct DeviceStatus {
	static constexpr size_t REASON_CAPACITY = 160;
	DeviceIo io = DeviceIo::OK;
	char reason[REASON_CAPACITY] = {};
};

// A device with its own I/O thread (device_exchange.h): how its transfers keep up.
struct DeviceIoStats {
	uint64_t cycles = 0; // I/O transfers completed.
	uint64_t commands_sent = 0; // Commands taken by the I/O side (a slow device skips some).
	double command_age_mean_s = 0.0; // Servo write -> on the wire.
	double command_age_max_s = 0.0;
	double cycle_cost_max_s = 0.0; // Longest single I/O cycle.
};

class HapticDevice {
public:
	virtual ~HapticDevice() = default;

	virtual Status open() = 0;
	// Idempotent. Writes zero force first if the device is still reachable.
	virtual void close() = 0;
	virtual bool is_open() const = 0;
	// Moves the reference position to the current one, or homes, where the hardware needs it.
	virtual Status calibrate() = 0;
	virtual DeviceCapabilities capabilities() const = 0;
	DeviceLimits limits() const { return capabilities().limits; }
	// Human-readable model name; valid for the device's lifetime.
	virtual const char *name() const = 0;
	// Game thread, any time. The default reports OK: devices whose I/O runs on the servo
	// thread report faults through DeviceIo.
	virtual DeviceStatus status() const { return {}; }
	// Zeros for devices whose I/O runs inside the servo tick.
	virtual DeviceIoStats io_stats() const { return {}; }

	// Called once per servo tick before read_state with the tick's period: simulations
	// integrate here, polled hardware can start a transfer.
	virtual void begin_tick(double p_dt_s) { (void)p_dt_s; }
	virtual DeviceIo read_state(DeviceState &r_state) = 0;
	virtual DeviceIo write_force(const ForceCommand &p_command) = 0;
	DeviceIo write_zero() { return write_force(ForceCommand{}); }

	// The device's cable when it exists in software (software_cable.h); nullptr for hardware.
	virtual SoftwareCable *software_cable() { return nullptr; }

	// Only devices in software (the simulated one, development builds' models) have a hand the
	// game can move.
	virtual bool has_hand() const { return false; }
	virtual Status set_hand_target(const Vec3 &p_target_m) {
		(void)p_target_m;
		return Status::error(StatusCode::UNSUPPORTED, "device '%s' has no simulated hand", name());
	}
};

} // namespace haptics
