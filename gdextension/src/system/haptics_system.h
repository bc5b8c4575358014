#pragma once

// The facade the Godot binding wraps: one object assembled from the core's servo, the
// renderers of the renderer table (renderer_table.h) and a device backend, owning the device,
// the servo thread and the lock-free channels between them. Engine-free (no Godot) and
// exception-free; every fallible call returns a Status whose message names the offending
// parameter, and a rejected call leaves the previous state (frame, configuration, device)
// untouched.
//
// Threading: call every method from ONE thread (the game's main thread). The servo thread is
// internal; nothing here blocks on it except stop()/close_device() (which join it).
//
// Units and spaces: device space (coordinates.h: x right, y up, z toward the user), metres,
// newtons, seconds. The binding converts game vectors with game_to_device_direction() and
// game_to_device_scaled().
//
// Typical use:
//   HapticsSystem system;
//   system.open_simulated_device();
//   system.start(1000.0);                 // or system.step(0.001) in tests
//   each physics tick:  system.submit_frame(frame);  system.push_impact(...) on collisions
//   each frame:         system.input_vector(), system.forces(), system.drain_telemetry(...)
//   system.stop();  system.close_device();  // also done by the destructor
//
// What only one renderer offers (the maze's walls, Pong's ball) is reached through its own
// channels, system.renderers().<name>.channels, and its port class (ConstraintPort, PongPort):
//   ConstraintPort maze(system.renderers().constraint.channels);
//   maze.set_geometry(walls, count, mapping);  config.servo.render_mode = RenderMode::CONSTRAINT;

#include "core/base/status.h"
#include "core/base/vec3.h"
#include "core/device/device.h"
#include "core/render/force_components.h"
#include "core/render/frame.h"
#include "core/servo/servo_loop.h"
#include "core/servo/servo_output.h"
#include "core/servo/servo_rate.h"
#include "core/servo/servo_stats.h"
#include "devices/simulated_device.h"
#include "system/render_config.h"
#include "system/renderer_set.h"

#include <cstddef>
#include <memory>

namespace haptics {

class HapticsSystem {
public:
	HapticsSystem();
	~HapticsSystem(); // stop() then close_device(): zero force is written before the join.

	HapticsSystem(const HapticsSystem &) = delete;
	HapticsSystem &operator=(const HapticsSystem &) = delete;

	// --- Devices -------------------------------------------------------------------------
	// Opens p_device and makes it current. If it fails to open, the current device (if
	// any) stays open and rendering is untouched; if it opens, rendering is stopped and the
	// previous device closed first. Every (re)open starts with the start-up ramp.
	Status open_device(std::unique_ptr<HapticDevice> p_device);
	Status open_simulated_device(const SimulatedDeviceConfig &p_config = {});
	// Stops rendering (zero force, join) and closes the device. Idempotent.
	void close_device();
	bool has_device() const;
	const char *device_name() const; // "" without a device.
	DeviceLimits device_limits() const; // Zeros without a device.
	DeviceCapabilities device_capabilities() const; // Defaults without a device.
	// The device's own report (why it failed, e.g. the USB error); OK without a device.
	DeviceStatus device_status() const;
	// The current device (nullptr without one); game thread, for what only its class offers
	// (software_cable(), to unplug a simulated device).
	HapticDevice *current_device();
	Status calibrate(); // Not while rendering.

	// --- Rendering -----------------------------------------------------------------------
	// Starts the servo thread at p_rate_hz in [250, 4000] (default 1000).
	Status start(double p_rate_hz = DEFAULT_RATE_HZ);
	Status start(const ServoOptions &p_options);
	// Zero force is written by the servo thread before it exits, then it is joined.
	// Idempotent; also ends a manual-step session.
	void stop();
	bool is_running() const;
	// Manual mode: one tick of p_dt_s in [1/4000, 1/250] s on the calling thread; no
	// thread, exactly deterministic. The first step after open/start/stop begins a session
	// (start-up ramp from zero). Not while the thread runs.
	Status step(double p_dt_s);
	// OK, or why rendering stopped on its own (e.g. the device was unplugged), with the
	// device's own reason when it gave one.
	Status servo_status() const;

	// --- Game -> servo -------------------------------------------------------------------
	// The latest frame; validated, then published lock-free. Rejected frames are counted in
	// stats().frames_rejected and the previous frame stays in force.
	// p_space: the game it comes from (a 3D game's values come in their 3D form: coordinates.h).
	Status submit_frame(const Frame &p_frame, GameSpace p_space = GameSpace::PLANE);
	// A frame refused before it was one (bytes that did not decode): counted with the rest.
	void count_rejected_frame();
	// Queues an impact transient. A full queue is not an error: the drop is counted in
	// stats().transient_drops and OK is returned.
	Status push_impact(const ImpactEvent &p_event);
	// Target of the simulated hand, m (finite, |target| <= 1).
	Status set_hand_target(const Vec3 &p_target_m);

	// --- Servo -> game (latest tick) -----------------------------------------------------
	Vec3 input_vector() const;
	Vec3 device_position() const;
	ForceComponents forces() const;
	ServoOutput output() const; // Everything above plus gains, flags and counters.
	ServoStats stats() const;
	// The wake-up latency's histogram since the servo started (1 us bins from 0, the last
	// holding everything beyond) into r_bins, up to p_capacity bins; returns how many it has.
	// For a benchmark that pools the ticks of several runs.
	size_t latency_bins(uint32_t *r_bins, size_t p_capacity) const;
	// Pops up to p_max_samples telemetry samples into r_out, which must hold
	// p_max_samples * TELEMETRY_STRIDE floats (layout in telemetry.h); returns how many.
	size_t drain_telemetry(float *r_out, size_t p_max_samples);

	// --- Configuration (any time, also while rendering) ----------------------------------
	// Validates the whole configuration (config_table.h) and hands it to the servo, which
	// picks it up at its next tick; on error nothing changes. To change one field:
	//   RenderConfig config = system.config();  config.servo.safety.force_scale = 0.5;
	//   system.configure(config);
	// A change of render_mode starts the new renderer from rest (the proxy is re-placed);
	// the slew limit smooths the change.
	Status configure(const RenderConfig &p_config);
	const RenderConfig &config() const;

	// --- Renderers -----------------------------------------------------------------------
	// Each renderer of the table with its channels, by name (renderers().pong.channels).
	RendererSet &renderers();

private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

} // namespace haptics
