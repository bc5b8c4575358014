#pragma once

// One servo tick, shared by the servo thread and manual step(dt):
//
//   device: advance + read  ->  pick up new config / frame, take impacts off the queue,
//   every renderer picks up its own inputs (walls, Pong's input and commands) -> input
//   vector -> the active renderer
//   (renderer.h) -> force scale -> transients (raw) -> safety (slew, watchdog, ramp,
//   finite, clamp) -> device: write -> publish output snapshot, push telemetry.
//
// ServoChannels is everything the game thread and the servo share; every member is
// lock-free and allocation-free after construction. The pipeline itself is owned by the
// servo while it runs and touched by the game thread only while it does not.

#include "core/config.h"
#include "core/constraint_renderer.h"
#include "core/force_model.h"
#include "core/frame.h"
#include "core/geometry_exchange.h"
#include "core/movement_renderer.h"
#include "core/pong_renderer.h"
#include "core/renderer.h"
#include "core/safety.h"
#include "core/seqlock.h"
#include "core/servo_output.h"
#include "core/servo_stats.h"
#include "core/spsc_queue.h"
#include "core/telemetry.h"
#include "core/transients.h"
#include "devices/device.h"
#include "pong/pong_channels.h"

#include <atomic>
#include <cstdint>

namespace haptics {

inline constexpr size_t IMPACT_QUEUE_CAPACITY = 64;
inline constexpr size_t TELEMETRY_QUEUE_CAPACITY = 4096; // 4 s at 1 kHz.

struct ServoChannels {
	Seqlock<Frame> frame; // Game -> servo, written by submit_frame only.
	Seqlock<RenderConfig> config; // Game -> servo.
	SpscQueue<ImpactEvent, IMPACT_QUEUE_CAPACITY> impacts; // Game -> servo.
	Seqlock<ServoOutput> output; // Servo -> game.
	SpscQueue<TelemetrySample, TELEMETRY_QUEUE_CAPACITY> telemetry; // Servo -> game.
	ServoStatsRecorder stats; // Servo -> game.
	std::atomic<uint64_t> queue_drops{ 0 }; // Impacts refused by a full queue (game side).
	GeometryExchange geometry; // Game -> servo walls; servo -> game the ones to free.
	PongChannels pong; // Pong's input and commands in, its state and events out.
};

class ServoPipeline {
public:
	explicit ServoPipeline(ServoChannels &r_channels);

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
	void apply_config(const RenderConfig &p_config);
	void pick_up_inputs();
	Renderer &active() { return *renderers_[static_cast<size_t>(config_.render_mode)]; }
	void publish(const DeviceState &p_state, const Vec3 &p_input, const ForceComponents &p_forces,
			const SafetyResult &p_safety, uint32_t p_renderer_flags);

	ServoChannels &channels_;
	HapticDevice *device_ = nullptr;
	double dt_s_ = 0.001;
	double time_s_ = 0.0;
	uint64_t tick_ = 0;

	RenderConfig config_;
	uint64_t config_version_ = 0;
	DeviceLimits limits_;
	DeviceCapabilities capabilities_;
	double input_radius_m_ = 0.1;

	Frame frame_;
	uint64_t frame_version_ = 0;
	bool new_frame_ = false;
	// The game's latest sign of life for the watchdog: a frame, or the active renderer's own
	// input (Renderer::heard_from_game).
	bool have_heartbeat_ = false;
	double last_heartbeat_s_ = 0.0;
	uint64_t frames_received_ = 0;

	MovementRenderer movement_;
	ConstraintRenderer constraint_;
	PongRenderer pong_;
	// Indexed by RenderMode.
	Renderer *const renderers_[RENDER_MODE_COUNT] = { &movement_, &constraint_, &pong_ };
	RenderResult rendered_; // The active renderer's result of this tick, written in place.
	TransientBank transients_;
	SafetyStage safety_;

	uint64_t telemetry_drops_ = 0;
	uint64_t clamped_ticks_ = 0;
	uint64_t non_finite_ticks_ = 0;
	uint32_t telemetry_countdown_ = 0;
};

} // namespace haptics
