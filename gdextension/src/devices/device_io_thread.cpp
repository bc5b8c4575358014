#include "devices/device_io_thread.h"

#include "core/base/realtime.h"

#include <cmath>
#include <system_error>

namespace haptics {

Status DeviceIoThread::start(DeviceIoWorker &r_worker, DeviceExchange &r_exchange, const DeviceIoThreadOptions &p_options) {
	if (!(p_options.rate_hz > 0.0 && p_options.rate_hz <= 4000.0)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "device I/O rate must be in (0, 4000] Hz (got %g)", p_options.rate_hz);
	}
	stop();
	worker_ = &r_worker;
	exchange_ = &r_exchange;
	options_ = p_options;
	stop_requested_.store(false, std::memory_order_relaxed);
	running_.store(true, std::memory_order_release);
	try {
		thread_ = std::thread([this] { run(); });
	} catch (const std::system_error &error) {
		running_.store(false, std::memory_order_release);
		return Status::error(StatusCode::DEVICE_ERROR, "could not start the device I/O thread: %s", error.what());
	}
	return Status::success();
}

void DeviceIoThread::stop() {
	stop_requested_.store(true, std::memory_order_release);
	if (thread_.joinable()) {
		thread_.join();
	}
	running_.store(false, std::memory_order_release);
}

void DeviceIoThread::run() {
	try_make_current_thread_realtime(options_.realtime_priority);
	const int64_t period_ns = std::llround(1e9 / options_.rate_hz);
	const double dt_s = static_cast<double>(period_ns) * 1e-9;
	int64_t deadline_ns = monotonic_now_ns();
	bool failed = false;
	while (!stop_requested_.load(std::memory_order_acquire)) {
		const int64_t begin_ns = monotonic_now_ns();
		exchange_->begin_transfer(begin_ns);
		const DeviceIo io = worker_->io_cycle(*exchange_, dt_s);
		exchange_->end_transfer();
		const int64_t end_ns = monotonic_now_ns();
		if (io != DeviceIo::OK) {
			if (exchange_->status().io == DeviceIo::OK) {
				exchange_->fail(io, "device I/O failed");
			}
			failed = true;
			break;
		}
		exchange_->record_cycle(static_cast<double>(end_ns - begin_ns) * 1e-9);
		deadline_ns += period_ns;
		if (end_ns - deadline_ns >= period_ns) {
			deadline_ns = end_ns; // A stalled bus: resume from now rather than replay.
		}
		sleep_until_ns(deadline_ns);
	}
	if (!failed) {
		worker_->io_stop();
	}
	running_.store(false, std::memory_order_release);
}

} // namespace haptics
