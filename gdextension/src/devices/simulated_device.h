#pragma once

// The default device and what tests use: a 3-DOF stylus of mass m inside an Omni-like
// workspace sphere, held by a simulated HAND. The hand is a spring-damper pulling the
// stylus toward a target that the game moves (mouse, keyboard, gamepad) or a test scripts:
//
//   m a = F_rendered + k_h (target - x) - b_h v
//
// so the rendered force is observable the way a user would feel it: push into a wall and
// the stylus settles short of the hand's target, at k_h (target - x) = -F_rendered.
//
// Integration: implicit (backward) Euler for the hand's linear spring-damper, with the
// rendered force held constant over the tick. It is unconditionally stable, so every
// servo rate of 250-4000 Hz works with any hand stiffness, and it is exact at equilibrium.
// The workspace boundary is a perfectly inelastic sphere (mechanical end stops).
// Deterministic: the same targets and forces at the same dt give bit-identical positions.
//
// `rigid_hand` makes the stylus follow the target exactly (clamped to the workspace), for
// tests that want a known input vector whatever the rendered force.
//
// set_plugged(false) simulates pulling the USB cable: the servo calls then report
// DISCONNECTED and open() fails, until set_plugged(true).
//
// Threading: set_hand_target, set_buttons and set_plugged may be called from the game
// thread while the servo runs (lock-free); the rest follows HapticDevice's contract.

#include "core/base/seqlock.h"
#include "core/device/device.h"

#include <atomic>

namespace haptics {

struct SimulatedDeviceConfig {
	double workspace_radius_m = 0.10; // Omni-like (CHAI3D's table).
	double max_force_n = 3.3;
	double max_continuous_force_n = 0.88;
	double max_stiffness_n_per_m = 700.0;
	double stylus_mass_kg = 0.045;
	double hand_stiffness_n_per_m = 300.0; // A relaxed grip.
	double hand_damping_n_s_per_m = 4.0; // About 0.55 of critical with the defaults.
	bool rigid_hand = false;
};

// Checks ranges: radius (0, 1] m, forces (0, 100] N, mass (0, 10] kg, hand stiffness
// [0, 1e5] N/m, damping [0, 1e4] N s/m. The message names the field.
Status validate_simulated_device_config(const SimulatedDeviceConfig &p_config);

class SimulatedDevice final : public HapticDevice, public SoftwareCable {
public:
	explicit SimulatedDevice(const SimulatedDeviceConfig &p_config = {});

	Status open() override;
	void close() override;
	bool is_open() const override { return open_; }
	Status calibrate() override;
	DeviceCapabilities capabilities() const override;
	const char *name() const override;

	void begin_tick(double p_dt_s) override;
	DeviceIo read_state(DeviceState &r_state) override;
	DeviceIo write_force(const ForceCommand &p_command) override;

	DeviceStatus status() const override;

	bool has_hand() const override { return true; }
	// Finite, |target| <= 1 m (beyond the workspace the stylus rests on the boundary).
	Status set_hand_target(const Vec3 &p_target_m) override;

	// Nothing presses them yet: for the device issue's button tests and Pong's fire button.
	void set_buttons(uint32_t p_buttons) { buttons_.store(p_buttons, std::memory_order_relaxed); }
	SoftwareCable *software_cable() override { return this; }
	void set_plugged(bool p_plugged) override { plugged_.store(p_plugged, std::memory_order_release); }
	bool plugged() const { return plugged_.load(std::memory_order_acquire); }

	const SimulatedDeviceConfig &config() const { return config_; }

private:
	Vec3 clamp_to_workspace(const Vec3 &p_position) const;

	SimulatedDeviceConfig config_;
	bool open_ = false;
	Seqlock<Vec3> hand_target_;
	Vec3 target_; // Servo thread's copy.
	std::atomic<uint32_t> buttons_{ 0 };
	std::atomic<bool> plugged_{ true };
	// Servo-thread state.
	Vec3 position_;
	Vec3 velocity_;
	Vec3 force_;
};

} // namespace haptics
