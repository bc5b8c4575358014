#pragma once

// The device interface every backend implements (CHAI3D's cGenericHapticDevice, reduced to
// what movement-based rendering needs). Device space: x right, y up, z toward the user,
// metres, newtons (coordinates.h).
//
// Threading contract, which the engine upholds:
//  - open, close, calibrate, limits, name, set_hand_target: the game thread, never while
//    the servo is running for close/open/calibrate.
//  - begin_tick, read_state, write_force: the servo thread (or the caller of step()), one
//    at a time. They must not allocate, lock a mutex that a non-real-time thread can hold,
//    or log; a bus transfer is the only blocking allowed.
//  - A device that disappears (unplugged) reports DeviceIo::DISCONNECTED from the servo
//    calls; the servo then stops rendering and the engine reports the error.

#include "core/status.h"
#include "core/vec3.h"

#include <cstdint>

namespace haptics {

struct DeviceLimits {
	double max_force_n = 0.0; // Peak force the device may be commanded, N.
	double max_continuous_force_n = 0.0; // Sustainable force, N (informational).
	double max_stiffness_n_per_m = 0.0; // Highest stable virtual stiffness, N/m.
	double workspace_radius_m = 0.0; // Radius of the usable workspace sphere, m.
};

struct DeviceState {
	Vec3 position_m; // Stylus tip, relative to the workspace centre.
	// Renderers receive it (RenderInput::device); none reads it yet. Kept for what comes
	// next: Haptic Battle Pong's paddle swing and the real devices that report a velocity.
	Vec3 velocity_m_per_s;
	uint32_t buttons = 0; // Bit b set when button b is pressed.
};

enum class DeviceIo : int32_t {
	OK = 0,
	DISCONNECTED = 1,
	FAILED = 2, // Any other I/O failure; rendering stops too.
};

class HapticDevice {
public:
	virtual ~HapticDevice() = default;

	virtual Status open() = 0;
	// Idempotent. Writes zero force first if the device is still reachable.
	virtual void close() = 0;
	virtual bool is_open() const = 0;
	// Moves the reference position to the current one where the hardware needs it.
	virtual Status calibrate() = 0;
	virtual DeviceLimits limits() const = 0;
	// Human-readable model name; valid for the device's lifetime.
	virtual const char *name() const = 0;

	// Called once per servo tick before read_state with the tick's period: simulations
	// integrate here, polled hardware can start a transfer.
	virtual void begin_tick(double p_dt_s) { (void)p_dt_s; }
	virtual DeviceIo read_state(DeviceState &r_state) = 0;
	virtual DeviceIo write_force(const Vec3 &p_force_n) = 0;

	// Only the simulated device has a hand the game can move.
	virtual bool has_hand() const { return false; }
	virtual Status set_hand_target(const Vec3 &p_target_m) {
		(void)p_target_m;
		return Status::error(StatusCode::UNSUPPORTED, "device '%s' has no simulated hand", name());
	}
};

} // namespace haptics
