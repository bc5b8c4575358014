#pragma once

// The seam between the servo pipeline and what it renders. Each tick the pipeline reads the
// device, picks up the game's inputs and asks the active renderer for a force; the impact
// transients and the safety stage (core/servo/servo_pipeline.h) then apply to every renderer
// alike. The core knows no renderer: the system assembles them (system/renderer_table.h),
// and ServoConfig::render_mode is the active one's index in the list the pipeline is given.
//
// Besides this interface a renderer class offers, for the system: `Config` (its settings, a
// schema value: its fields' ranges are checked from the schema), `Channels` (derived from
// RendererChannels: a Seqlock<Config> `settings` and whatever else it shares with the game),
// `Port` (what it takes from and gives GDScript, core/render/renderer_port.h; NoPort for
// nothing), a constructor taking its Channels, and a static `const RendererInfo &info()`;
// optionally a static `Status validate(const Config &)` for limits that join its fields.
//
// Call order, all on the thread that ticks the servo, none of it may allocate, lock, block
// or log:
//   pick_up_settings(dt, restart)  every renderer, first, on a tick that picked up a new
//                       servo configuration (the game publishes one after any renderer's
//                       settings: ServoChannels::config) or a new period, and at a session's
//                       start with restart: take the renderer's settings off its channel when
//                       the game changed them, and follow the period. Keep what a parameter
//                       change does not invalidate (a filter's motion).
//   begin_session(dt)   a rendering session starts (every renderer): counters zeroed, rest.
//   reset()             the renderer becomes the active one: start from rest.
//   pick_up()           every tick, every renderer: take the renderer's own game inputs off
//                       its lock-free channels, so a hand-over never waits for a mode switch.
//   render(in, out)     every tick, the active renderer only: it overwrites every field of
//                       the result except forces.smoothed, .impact and .total (the
//                       pipeline's), in place, so the tick builds no result of its own.
//   publish(forces, act) every tick, every renderer: its state for the game (act: active;
//                       forces: the tick's, scaled, as felt).

#include "core/base/vec3.h"
#include "core/device/device.h"
#include "core/render/force_components.h"
#include "core/render/frame.h"

#include <cstdint>

namespace haptics {

struct RenderInput {
	const DeviceState &device;
	Vec3 input; // Input vector i: the device position over the input radius, dead zone applied.
	const Frame &frame; // The latest frame the game submitted (empty before the first).
	bool new_frame; // It arrived this tick.
	double dt_s;
	double device_radius_m; // The device's workspace radius.
	bool has_orientation; // device.orientation is meaningful (DeviceCapabilities).
};

struct RenderResult {
	// Components for the HUD and telemetry; `continuous` is their sum. The pipeline scales
	// them by the force scale and fills smoothed, impact and total.
	ForceComponents forces;
	// The continuous force handed to the safety stage: `forces.continuous` after whatever
	// filtering the renderer does (the movement model smooths its 50 Hz steps; a
	// position-feedback renderer must not, a filter in its loop adds lag).
	Vec3 continuous;
	uint32_t flags = 0; // The renderer's own telemetry flags (RendererInfo::telemetry_flags).
};

class Renderer {
public:
	virtual ~Renderer() = default;

	virtual void pick_up_settings(double p_dt_s, bool p_restart) = 0;
	virtual void begin_session(double p_dt_s) {
		(void)p_dt_s;
		reset();
	}
	virtual void reset() = 0;
	virtual void pick_up() {}
	// True when this tick's pick_up() took the game input that is the active renderer's
	// heartbeat (Pong's PongInput, sent every frame instead of frames): the watchdog then
	// counts it as the game being alive, like a new frame.
	virtual bool heard_from_game() const { return false; }
	// A renderer of a 2D game: the servo holds a 3-DOF device's depth axis (PlaneHoldConfig).
	virtual bool planar() const { return true; }
	virtual void render(const RenderInput &p_input, RenderResult &r_result) = 0;
	virtual void publish(const ForceComponents &p_forces, bool p_active) {
		(void)p_forces;
		(void)p_active;
	}
};

} // namespace haptics
