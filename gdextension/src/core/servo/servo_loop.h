#pragma once

// The servo thread: ticks a ServoPipeline at a fixed rate on absolute deadlines.
//
// Each iteration sleeps until the next deadline (clock_nanosleep TIMER_ABSTIME on
// CLOCK_MONOTONIC), ticks, records timing, and moves the deadline on by exactly one period,
// so the rate does not drift however late a wake-up is. After a stall of more than a whole
// period the missed deadlines are skipped (and counted) rather than replayed in a burst:
// a burst of ticks renders nothing a hand could feel and delays the next real one.
//
// At start the thread asks for what ServoOptions::realtime names (SCHED_FIFO priority, locked
// memory, the CPU wake-up latency held at 0, pinning, a prefaulted stack; realtime.h), each
// falling back quietly when refused; stats say what was granted. The process-wide holds are
// released when the thread ends. With a spin (ServoOptions::spin_ns) it sleeps until that
// long before each deadline and busy-waits the rest, absorbing the wake-up's lateness at a CPU cost
// (ServoStats::thread_cpu_fraction); with real time but no latency hold the spin is learned
// from the thread's own wake-ups (wake_ahead.h).
//
// Stopping: stop() raises a flag, the thread finishes its tick, writes ZERO force to the
// device itself, and only then exits; stop() joins it. So the last thing the device receives
// from a stopping servo is always zero, before anyone can close it (the classic crash on
// exit is a device closed under a running I/O thread). A device I/O failure (unplugged)
// ends the thread the same way and leaves state() == FAULTED until stop() or start().

#include "core/base/realtime.h"
#include "core/base/status.h"
#include "core/device/device.h"
#include "core/servo/servo_pipeline.h"
#include "core/servo/wake_ahead.h"

#include <atomic>
#include <cstdint>
#include <thread>

namespace haptics {

// The servo thread's name, as the system shows it.
inline constexpr const char *SERVO_THREAD_NAME = "haptics-servo";

enum class ServoState : int32_t {
	STOPPED = 0,
	RUNNING = 1,
	FAULTED = 2, // The thread ended itself on a device error; join with stop().
};

enum class LoopScheduling : int32_t {
	DEADLINE = 0, // Absolute deadlines: the product.
	NAIVE_SLEEP = 1, // sleep_for(period) after each tick: the benchmark's baseline only.
};

struct ServoOptions {
	double rate_hz = 1000.0; // [250, 4000]
	LoopScheduling scheduling = LoopScheduling::DEADLINE;
	RealtimeRequest realtime; // What the thread asks of the system (defaults: realtime.h).
	// Busy-wait before each deadline (DEADLINE scheduling only); 0 = sleep to the deadline.
	// [0, half a period], or SPIN_AUTO, chosen by what the thread was granted, each by
	// measurement (docs/servo-timing.md):
	//   - real time with /dev/cpu_dma_latency held (root): DEFAULT_SPIN_NS, a lower p99 wake
	//     latency idle, under CPU and under rendering load for about 1 % of a core.
	//   - real time without the hold (an ordinary user's SCHED_RR from RealtimeKit, without
	//     the udev rule): learned (wake_ahead.h), from UNHELD_SPIN_NS. An idle core may sleep
	//     deeper and wake later, by how much depends on the machine.
	//   - SCHED_OTHER: none. A thread that is not real-time is preempted mid-spin by the
	//     load it competes with, which made its p99 under CPU load several times worse.
	int64_t spin_ns = SPIN_AUTO;

	static constexpr int64_t SPIN_AUTO = -1;
	static constexpr int64_t DEFAULT_SPIN_NS = haptics::DEFAULT_SPIN_NS; // servo.schema.toml
	static constexpr int64_t UNHELD_SPIN_NS = haptics::UNHELD_SPIN_NS;
};

// The spin a servo with p_options spins once granted p_grants (SPIN_AUTO resolved); where it
// learns the spin, the one it starts from.
int64_t effective_spin_ns(const ServoOptions &p_options, const RealtimeGrants &p_grants);
// Whether that servo learns its spin: SPIN_AUTO, real time, no latency hold.
bool learns_spin(const ServoOptions &p_options, const RealtimeGrants &p_grants);

// The longest spin_ns a servo at p_rate_hz (a valid rate) accepts: half its period, so a tick
// always has the other half to run in.
int64_t max_spin_ns(double p_rate_hz);

class ServoLoop {
public:
	ServoLoop(ServoPipeline &r_pipeline, ServoChannels &r_channels);
	~ServoLoop(); // Stops (zero force, join).

	ServoLoop(const ServoLoop &) = delete;
	ServoLoop &operator=(const ServoLoop &) = delete;

	// Game thread. Begins a pipeline session on p_device and spawns the thread. Options must
	// be valid; the loop must not be running (a FAULTED loop is joined first).
	Status start(HapticDevice *p_device, const ServoOptions &p_options);
	// Game thread. Idempotent; returns once the thread has written zero and exited. A
	// FAULTED state survives stop() so the game can still ask why rendering ended.
	void stop();
	// Game thread: stop(), then forget a fault (a new device or a manual session).
	void clear_fault();

	ServoState state() const { return state_.load(std::memory_order_acquire); }
	// The I/O status that ended the last run (OK unless FAULTED).
	DeviceIo fault() const { return fault_.load(std::memory_order_acquire); }
	RealtimeResult scheduler() const;
	// What the thread was granted (all false / -1 / 0 until it has started).
	RealtimeGrants grants() const;
	// The spin the thread uses now (effective_spin_ns, then what it learns; until it has its
	// grants, the spin asked for, or 0 for SPIN_AUTO).
	int64_t spin_ns() const;
	// Whether the thread learns its spin (learns_spin; false until it has its grants).
	bool spin_learned() const;
	const ServoOptions &options() const { return options_; }

private:
	void run();

	ServoPipeline &pipeline_;
	ServoChannels &channels_;
	HapticDevice *device_ = nullptr;
	ServoOptions options_;
	std::thread thread_;
	std::atomic<bool> stop_requested_{ false };
	std::atomic<ServoState> state_{ ServoState::STOPPED };
	std::atomic<DeviceIo> fault_{ DeviceIo::OK };
	// Written by the thread once at start, then published; read by the game thread.
	RealtimeGrants grants_;
	bool learns_spin_ = false;
	std::atomic<bool> grants_published_{ false };
	std::atomic<int64_t> spin_ns_{ 0 }; // Written by the thread as it learns.
	WakeAhead wake_ahead_; // The thread's alone.
};

} // namespace haptics
