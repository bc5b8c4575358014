#include "core/servo_loop.h"

#include <cmath>
#include <system_error>

namespace haptics {

namespace {

constexpr double S_PER_NS = 1e-9;

} // namespace

ServoLoop::ServoLoop(ServoPipeline &r_pipeline, ServoChannels &r_channels) :
		pipeline_(r_pipeline), channels_(r_channels) {}

ServoLoop::~ServoLoop() {
	stop();
}

RealtimeResult ServoLoop::scheduler() const {
	RealtimeResult result;
	result.kind = scheduler_kind_.load(std::memory_order_acquire);
	result.priority = scheduler_priority_.load(std::memory_order_acquire);
	return result;
}

Status ServoLoop::start(HapticDevice *p_device, const ServoOptions &p_options) {
	if (state() == ServoState::RUNNING) {
		return Status::error(StatusCode::INVALID_STATE, "the servo is already running");
	}
	stop(); // Joins a thread that ended on a fault.
	device_ = p_device;
	options_ = p_options;
	const int64_t period_ns = std::llround(1e9 / options_.rate_hz);
	pipeline_.begin_session(p_device, static_cast<double>(period_ns) * S_PER_NS);
	channels_.stats.reset(options_.rate_hz);
	stop_requested_.store(false, std::memory_order_relaxed);
	fault_.store(DeviceIo::OK, std::memory_order_relaxed);
	scheduler_kind_.store(SchedulerKind::NORMAL, std::memory_order_relaxed);
	scheduler_priority_.store(0, std::memory_order_relaxed);
	state_.store(ServoState::RUNNING, std::memory_order_release);
	try {
		thread_ = std::thread([this] { run(); });
	} catch (const std::system_error &error) {
		state_.store(ServoState::STOPPED, std::memory_order_release);
		return Status::error(StatusCode::INVALID_STATE, "could not start the servo thread: %s", error.what());
	}
	return Status::success();
}

void ServoLoop::stop() {
	stop_requested_.store(true, std::memory_order_release);
	if (thread_.joinable()) {
		thread_.join();
	}
	ServoState expected = ServoState::RUNNING;
	state_.compare_exchange_strong(expected, ServoState::STOPPED, std::memory_order_acq_rel);
}

void ServoLoop::clear_fault() {
	stop();
	state_.store(ServoState::STOPPED, std::memory_order_release);
	fault_.store(DeviceIo::OK, std::memory_order_release);
}

void ServoLoop::run() {
	const RealtimeResult realtime = try_make_current_thread_realtime(options_.realtime_priority);
	scheduler_kind_.store(realtime.kind, std::memory_order_release);
	scheduler_priority_.store(realtime.priority, std::memory_order_release);

	const int64_t period_ns = std::llround(1e9 / options_.rate_hz);
	const double dt_s = static_cast<double>(period_ns) * S_PER_NS;
	const bool naive = options_.scheduling == LoopScheduling::NAIVE_SLEEP;
	int64_t deadline_ns = monotonic_now_ns() + period_ns;
	int64_t previous_wake_ns = -1;
	DeviceIo io = DeviceIo::OK;

	while (!stop_requested_.load(std::memory_order_acquire)) {
		if (naive) {
			sleep_for_ns(period_ns);
		} else {
			sleep_until_ns(deadline_ns);
		}
		const int64_t wake_ns = monotonic_now_ns();
		io = pipeline_.tick(dt_s);
		const int64_t end_ns = monotonic_now_ns();

		// The naive loop has no deadline; its lateness is how much longer than a period
		// this tick came after the previous one.
		const int64_t lateness_ns = naive ? (previous_wake_ns < 0 ? 0 : wake_ns - previous_wake_ns - period_ns)
										  : wake_ns - deadline_ns;
		const double period_s = previous_wake_ns < 0 ? -1.0 : static_cast<double>(wake_ns - previous_wake_ns) * S_PER_NS;
		channels_.stats.record_tick(static_cast<double>(wake_ns) * S_PER_NS, period_s,
				static_cast<double>(lateness_ns) * S_PER_NS, static_cast<double>(end_ns - wake_ns) * S_PER_NS);
		previous_wake_ns = wake_ns;
		if (io != DeviceIo::OK) {
			break;
		}

		deadline_ns += period_ns;
		if (!naive && end_ns - deadline_ns >= period_ns) {
			const int64_t missed = (end_ns - deadline_ns) / period_ns;
			deadline_ns += missed * period_ns;
			channels_.stats.record_missed(static_cast<uint64_t>(missed));
		}
	}

	// Zero force before the thread ends, whatever ended it. Harmless if the device is gone.
	device_->write_zero();
	fault_.store(io, std::memory_order_release);
	state_.store(io == DeviceIo::OK ? ServoState::STOPPED : ServoState::FAULTED, std::memory_order_release);
}

} // namespace haptics
