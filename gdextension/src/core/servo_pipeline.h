#pragma once

// One servo tick, shared by the servo thread and manual step(dt):
//
//   device: advance + read  ->  pick up new config / frame / wall geometry, take impacts
//   off the queue -> input vector -> force model -> smoothing (continuous part)
//   -> transients (raw) -> safety (slew, watchdog, ramp, finite, clamp) -> device: write
//   -> publish output snapshot, push telemetry, record nothing slow.
//
// In RenderMode::CONSTRAINT the force model and smoothing are replaced by the constraint
// renderer (finite proxy against the walls, F = k_c (proxy - device), reported as the
// `normal` component). It is not low-pass filtered: a filter inside a position-feedback
// loop adds phase lag, which makes a stiff wall spongy and can make it unstable, and the
// force is already continuous at the servo rate. Transients and the whole safety stage
// apply unchanged.
//
// ServoChannels is everything the game thread and the servo share; every member is
// lock-free and allocation-free after construction. The pipeline itself is owned by the
// servo while it runs and touched by the game thread only while it does not.

#include "core/config.h"
#include "core/constraint_renderer.h"
#include "core/force_model.h"
#include "core/frame.h"
#include "core/geometry_exchange.h"
#include "core/safety.h"
#include "core/seqlock.h"
#include "core/servo_stats.h"
#include "core/smoothing_filter.h"
#include "core/spsc_queue.h"
#include "core/telemetry.h"
#include "core/transients.h"
#include "devices/device.h"

#include <atomic>
#include <cstdint>

namespace haptics {

inline constexpr size_t IMPACT_QUEUE_CAPACITY = 64;
inline constexpr size_t TELEMETRY_QUEUE_CAPACITY = 4096; // 4 s at 1 kHz.

// Servo -> game, republished every tick.
struct ServoOutput {
	double time_s = 0.0; // Servo time since the session started.
	uint64_t tick = 0;
	Vec3 input; // Input vector i.
	Vec3 position_m; // Device position.
	uint32_t buttons = 0;
	uint32_t flags = 0; // TelemetryFlag bits of this tick.
	ForceComponents forces;
	double frame_age_s = -1.0; // -1 before the first frame.
	double ramp_gain = 0.0;
	double watchdog_gain = 0.0;
	uint64_t frames_received = 0;
	uint64_t bank_drops = 0; // Transients dropped because the bank was full.
	uint64_t telemetry_drops = 0;
	uint64_t clamped_ticks = 0;
	uint64_t non_finite_ticks = 0;
	// Constraint renderer (RenderMode::CONSTRAINT); maze units. Before the proxy is placed
	// (or in MOVEMENT mode) proxy_maze is the goal, i.e. the device mapped into the maze.
	RenderMode render_mode = RenderMode::MOVEMENT;
	Vec2 proxy_maze;
	Vec2 goal_maze;
	uint32_t proxy_constraints = 0; // Walls holding the proxy: 0 free, 1 sliding, 2+ stopped.
	bool proxy_placed = false;
	uint64_t proxy_updates = 0; // Proxy updates this session (1 per tick, or 1 per frame).
	// The walls the servo holds: how many geometries it has picked up since the engine was
	// made (a set_constraint_geometry has taken effect once this moves), and their count.
	uint64_t geometry_generation = 0;
	uint32_t geometry_segments = 0;
};

struct ServoChannels {
	Seqlock<Frame> frame; // Game -> servo, written by submit_frame only.
	Seqlock<RenderConfig> config; // Game -> servo.
	SpscQueue<ImpactEvent, IMPACT_QUEUE_CAPACITY> impacts; // Game -> servo.
	Seqlock<ServoOutput> output; // Servo -> game.
	SpscQueue<TelemetrySample, TELEMETRY_QUEUE_CAPACITY> telemetry; // Servo -> game.
	ServoStatsRecorder stats; // Servo -> game.
	std::atomic<uint64_t> queue_drops{ 0 }; // Impacts refused by a full queue (game side).
	GeometryExchange geometry; // Game -> servo walls; servo -> game the ones to free.
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
	void apply_config(const RenderConfig &p_config, bool p_force_filter);
	void pick_up_inputs();
	void publish(const DeviceState &p_state, const Vec3 &p_input, const ForceComponents &p_forces,
			const SafetyResult &p_safety, bool p_new_frame, bool p_contact);
	// The constraint renderer's forces for this tick (normal and continuous filled).
	ForceComponents render_constraint(const DeviceState &p_state);

	ServoChannels &channels_;
	HapticDevice *device_ = nullptr;
	double dt_s_ = 0.001;
	double time_s_ = 0.0;
	uint64_t tick_ = 0;

	RenderConfig config_;
	uint64_t config_version_ = 0;
	DeviceLimits limits_;
	double input_radius_m_ = 0.1;

	Frame frame_;
	uint64_t frame_version_ = 0;
	bool have_frame_ = false;
	bool new_frame_ = false;
	double last_frame_time_s_ = 0.0;
	uint64_t frames_received_ = 0;

	SmoothingFilter filter_;
	TransientBank transients_;
	SafetyStage safety_;

	ConstraintRenderer constraint_;
	ConstraintOutput constraint_output_;
	uint64_t proxy_updates_ = 0;

	uint64_t telemetry_drops_ = 0;
	uint64_t clamped_ticks_ = 0;
	uint64_t non_finite_ticks_ = 0;
	uint32_t telemetry_countdown_ = 0;
};

} // namespace haptics
