#pragma once

// How a device whose I/O is slower than (or independent of) the servo meets the 1 kHz tick
// without ever making it wait on a bus: the backend's own I/O thread (device_io_thread.h,
// or a vendor scheduler such as OpenHaptics') and the servo exchange only the LATEST value,
// each way, through seqlocks:
//
//   servo  --write_command-->  [Seqlock<StampedCommand>]  --latest_command-->  I/O thread
//   servo  <--read_state-----  [Seqlock<DeviceState>]     <--publish_state---  I/O thread
//
// A device running at 250 Hz thus gets, at each of its transfers, the newest force the
// servo computed (never a queue of stale ones), and the servo reads the newest position the
// device reported. Both sides only copy a few dozen bytes: no lock, no allocation, no wait.
// A fault seen by the I/O thread (unplugged, transfer error) is raised here and turns the
// servo's next read into DISCONNECTED/FAILED, so the servo writes zero and stops.
//
// Each command carries the servo's monotonic time, so the I/O side can measure how old the
// force was when it went on the wire (DeviceIoStats): the latency this design adds.

#include "core/base/realtime.h"
#include "core/base/seqlock.h"
#include "core/device/device.h"

#include <atomic>
#include <cstdarg>
#include <cstdint>

namespace haptics {

// A servo command and when the servo wrote it (CLOCK_MONOTONIC ns; 0 = never).
struct StampedCommand {
	ForceCommand command;
	int64_t written_ns = 0;
};

class DeviceExchange {
public:
	// --- Servo side (the servo thread only) -----------------------------------------------
	// The latest state; DISCONNECTED/FAILED once the I/O side has failed.
	DeviceIo read_state(DeviceState &r_state) const;
	DeviceIo write_command(const ForceCommand &p_command);

	// --- I/O side (one thread at a time) ------------------------------------------------------
	void publish_state(const DeviceState &p_state);
	// The newest command, to put on the wire now; its age (servo write -> now) goes into
	// stats(). A zero command before the servo has written any.
	ForceCommand latest_command();
	// Records what went wrong; the servo stops at its next read. The reason is one sentence.
	void fail(DeviceIo p_io, const char *p_format, ...) __attribute__((format(HAPTICS_PRINTF, 3, 4)));
	void record_cycle(double p_cycle_cost_s);
	// Around each transfer: a transfer under way longer than OUTPUT_STALL_S shows in status()
	// (a NAKing endpoint blocks a write for as long as it NAKs), and clears when it ends.
	void begin_transfer(int64_t p_now_ns) { transfer_began_ns_.store(p_now_ns, std::memory_order_release); }
	void end_transfer() { transfer_began_ns_.store(0, std::memory_order_release); }

	// --- Game side (open/close only, while no servo runs) -----------------------------------
	void reset(const DeviceState &p_initial = {});
	// Any time: the fault, or a transfer stuck past OUTPUT_STALL_S at p_now_ns.
	DeviceStatus status(int64_t p_now_ns) const;
	DeviceStatus status() const { return status(monotonic_now_ns()); }
	DeviceIoStats stats() const;
	// What calibrate() says for a device whose I/O runs through this exchange: ready while the
	// device p_name is open and its I/O has not failed.
	Status ready_status(bool p_open, const char *p_name) const;

private:
	Seqlock<StampedCommand> command_;
	Seqlock<DeviceState> state_;
	Seqlock<DeviceStatus> status_;
	std::atomic<DeviceIo> io_{ DeviceIo::OK };
	std::atomic<int64_t> transfer_began_ns_{ 0 }; // 0: no transfer under way.
	// I/O-thread statistics, read by the game.
	std::atomic<uint64_t> cycles_{ 0 };
	std::atomic<uint64_t> commands_sent_{ 0 };
	std::atomic<double> age_sum_s_{ 0.0 };
	std::atomic<double> age_max_s_{ 0.0 };
	std::atomic<double> cycle_cost_max_s_{ 0.0 };
	mutable DeviceState last_state_; // Servo's copy when a read races a publish.
};

} // namespace haptics
