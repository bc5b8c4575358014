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
#include "core/device/device.gen.h"
#include "core/device/software_cable.h"

#include <cstdint>

namespace haptics {

// DeviceLimits, ForceOutput, DeviceCapabilities, DeviceIo and DeviceStatus: device.schema.toml.
inline constexpr size_t DEVICE_REASON_CAPACITY = sizeof(DeviceStatus{}.reason.data);

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
