#pragma once

// One servo tick, shared by the servo thread and manual step(dt):
//
//   device: advance + read  ->  pick up new config (the servo's, then every renderer's own)
//   and the latest frame, take impacts off the queue, every renderer picks up its own inputs
//   (the maze's walls, Pong's input and commands) -> input vector -> the active renderer
//   (renderer.h) -> force scale -> transients (raw) -> safety (slew, watchdog, ramp,
//   finite, clamp) -> device: write -> publish output snapshot (and each renderer its own
//   state), push telemetry.
//
// The renderers are whatever the engine assembled, in render-mode order; the pipeline knows
// them only through renderer.h. It, and they, are owned by the servo while it runs and
// touched by the game thread only while it does not.

#include "core/device/device.h"
#include "core/render/frame.h"
#include "core/render/renderer.h"
#include "core/servo/frame_peak.h"
#include "core/servo/safety.h"
#include "core/servo/servo_channels.h"
#include "core/servo/servo_config.h"
#include "core/servo/transients.h"

#include <cstdint>
#include <span>

namespace haptics {

class ServoPipeline {
public:
	// p_renderers outlive the pipeline; ServoConfig::render_mode indexes them (validated by
	// the engine).
	ServoPipeline(ServoChannels &r_channels, std::span<Renderer *const> p_renderers);

	// Starts a rendering session on p_device at period p_dt_s: start-up ramp from zero,
	// filter and slew at rest, transients cleared, counters zeroed, the latest frame and
	// config picked up. Not concurrent with tick().
	void begin_session(HapticDevice *p_device, double p_dt_s);

	// One tick of p_dt_s. Returns the device's I/O status; on anything but OK nothing was
	// written and the caller must stop rendering.
	DeviceIo tick(double p_dt_s);

	double time_s() const { return time_s_; }
	uint64_t ticks() const { return tick_; }

private:
	// Returns whether the render mode changed.
	bool apply_config(const ServoConfig &p_config);
	void pick_up_inputs(bool p_period_changed);
	Renderer &active() { return *renderers_[static_cast<size_t>(config_.render_mode)]; }
	void publish(const DeviceState &p_state, const Vec3 &p_input, const ForceComponents &p_forces,
			const SafetyResult &p_safety, uint32_t p_renderer_flags);

	ServoChannels &channels_;
	HapticDevice *device_ = nullptr;
	double dt_s_ = 0.001;
	double time_s_ = 0.0;
	uint64_t tick_ = 0;

	ServoConfig config_;
	uint64_t config_version_ = 0;
	DeviceLimits limits_;
	DeviceCapabilities capabilities_;
	double input_radius_m_ = 0.1;

	GameFrame submitted_;
	uint64_t frame_version_ = 0;
	bool new_frame_ = false;
	// The game's latest sign of life for the watchdog: a frame, or the active renderer's own
	// input (Renderer::heard_from_game).
	bool have_heartbeat_ = false;
	double last_heartbeat_s_ = 0.0;
	uint64_t frames_received_ = 0;

	const std::span<Renderer *const> renderers_; // Indexed by render mode.
	RenderResult rendered_; // The active renderer's result of this tick, written in place.
	TransientBank transients_;
	SafetyStage safety_;
	FramePeak peak_;

	uint64_t telemetry_drops_ = 0;
	uint64_t clamped_ticks_ = 0;
	uint64_t non_finite_ticks_ = 0;
	uint32_t telemetry_countdown_ = 0;
};

} // namespace haptics
