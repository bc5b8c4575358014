#pragma once

// The thread a backend's bus I/O runs on, at the device's native rate on absolute deadlines
// (like the servo), so no USB transfer ever runs inside the servo tick. Each cycle the
// worker takes the newest force from the DeviceExchange, puts it on the wire, reads the
// device and publishes its state (device_exchange.h explains the hand-over).
//
// When a cycle fails the thread records why in the exchange (the servo stops at its next
// read: zero force, status on the HUD) and ends. stop() makes the thread run the worker's
// io_stop() (write zero while the device is still reachable) and joins it.

#include "core/base/status.h"
#include "devices/device_exchange.h"

#include <atomic>
#include <cstdint>
#include <thread>

namespace haptics {

class DeviceIoWorker {
public:
	virtual ~DeviceIoWorker() = default;
	// One transfer. Take the command with r_exchange.latest_command(), send it, read the
	// device, publish_state(); on failure call p_exchange.fail(...) with a reason and return
	// the error. Must not allocate (it runs for the whole session at up to kHz rates).
	virtual DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) = 0;
	// Last call on the I/O thread before it exits normally: write zero force.
	virtual void io_stop() {}
};

struct DeviceIoThreadOptions {
	double rate_hz = 1000.0; // (0, 4000]
	int32_t realtime_priority = 45; // Just below the servo's: the servo never waits on it.
};

class DeviceIoThread {
public:
	DeviceIoThread() = default;
	~DeviceIoThread() { stop(); }

	DeviceIoThread(const DeviceIoThread &) = delete;
	DeviceIoThread &operator=(const DeviceIoThread &) = delete;

	// The exchange and worker must outlive the thread (stop() before destroying them).
	Status start(DeviceIoWorker &r_worker, DeviceExchange &r_exchange, const DeviceIoThreadOptions &p_options);
	// Idempotent; joins.
	void stop();
	bool is_running() const { return running_.load(std::memory_order_acquire); }

private:
	void run();

	DeviceIoWorker *worker_ = nullptr;
	DeviceExchange *exchange_ = nullptr;
	DeviceIoThreadOptions options_;
	std::thread thread_;
	std::atomic<bool> stop_requested_{ false };
	std::atomic<bool> running_{ false };
};

} // namespace haptics
