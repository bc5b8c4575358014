#pragma once

// The seam between the servo pipeline and what it renders. Each tick the pipeline reads the
// device, picks up the game's inputs and asks the active renderer for a force; the impact
// transients and the safety stage (servo_pipeline.h) then apply to every renderer alike.
// Renderers: MovementRenderer (the paper's method), ConstraintRenderer (the maze's finite
// proxy), PongRenderer (Haptic Battle Pong's ball-paddle contact). A renderer is chosen by
// RenderConfig::render_mode, whose value is its index in the pipeline.
//
// Call order, all on the thread that ticks the servo, none of it may allocate, lock, block
// or log:
//   begin_session(dt)   a rendering session starts (every renderer): counters zeroed, rest.
//   configure(cfg, dt)  every configuration the servo picks up, and a change of period
//                       (every renderer, so a mode switch finds the new one current). Keep
//                       what a parameter change does not invalidate (a filter's motion).
//   reset()             the renderer becomes the active one: start from rest.
//   pick_up()           every tick, every renderer, first: take the renderer's own game
//                       inputs off its lock-free channel, so a hand-over never waits for a
//                       mode switch.
//   render(in, out)     every tick, the active renderer only: it overwrites every field of
//                       the result except forces.smoothed, .impact and .total (the
//                       pipeline's), in place, so the tick builds no result of its own.
//   publish(out, act)   every tick, every renderer: its state for the game (act: active).

#include "core/config.h"
#include "core/force_model.h"
#include "core/frame.h"
#include "core/servo_output.h"
#include "core/vec3.h"
#include "devices/device.h"

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
	uint32_t flags = 0; // The renderer's own TelemetryFlag bits.
};

class Renderer {
public:
	virtual ~Renderer() = default;

	virtual void begin_session(double p_dt_s) {
		(void)p_dt_s;
		reset();
	}
	virtual void configure(const RenderConfig &p_config, double p_dt_s) = 0;
	virtual void reset() = 0;
	virtual void pick_up() {}
	// True when this tick's pick_up() took the game input that is the active renderer's
	// heartbeat (Pong's PongInput, sent every frame instead of frames): the watchdog then
	// counts it as the game being alive, like a new frame.
	virtual bool heard_from_game() const { return false; }
	// A renderer of a 2D game: the servo holds a 3-DOF device's depth axis (PlaneHoldConfig).
	virtual bool planar() const { return true; }
	virtual void render(const RenderInput &p_input, RenderResult &r_result) = 0;
	virtual void publish(ServoOutput &r_output, bool p_active) const {
		(void)r_output;
		(void)p_active;
	}
};

} // namespace haptics
