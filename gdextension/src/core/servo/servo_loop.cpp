#include "core/servo/servo_loop.h"

#include <algorithm>
#include <cmath>
#include <system_error>

namespace haptics {

namespace {

constexpr double S_PER_NS = 1e-9;
// The thread's CPU time is read (a system call) once every this many ticks.
constexpr uint64_t CPU_SAMPLE_TICKS = 1000;

} // namespace

int64_t max_spin_ns(double p_rate_hz) {
	return std::llround(1e9 / p_rate_hz) / 2;
}

ServoLoop::ServoLoop(ServoPipeline &r_pipeline, ServoChannels &r_channels) :
		pipeline_(r_pipeline), channels_(r_channels) {}

ServoLoop::~ServoLoop() {
	stop();
}

RealtimeResult ServoLoop::scheduler() const {
	const RealtimeGrants granted = grants();
	RealtimeResult result;
	result.kind = granted.kind;
	result.priority = granted.priority;
	return result;
}

RealtimeGrants ServoLoop::grants() const {
	return grants_published_.load(std::memory_order_acquire) ? grants_ : RealtimeGrants{};
}

int64_t ServoLoop::spin_ns() const {
	// Before the thread has its grants, an explicit spin is already known; SPIN_AUTO is not.
	return grants_published_.load(std::memory_order_acquire) ? spin_ns_.load(std::memory_order_relaxed)
															 : effective_spin_ns(options_, RealtimeGrants{});
}

bool ServoLoop::spin_learned() const {
	return grants_published_.load(std::memory_order_acquire) && learns_spin_;
}

bool learns_spin(const ServoOptions &p_options, const RealtimeGrants &p_grants) {
	return p_options.scheduling == LoopScheduling::DEADLINE && p_options.spin_ns == ServoOptions::SPIN_AUTO &&
			is_realtime_kind(p_grants.kind) && !p_grants.cpu_latency_held;
}

int64_t effective_spin_ns(const ServoOptions &p_options, const RealtimeGrants &p_grants) {
	if (p_options.scheduling == LoopScheduling::NAIVE_SLEEP) {
		return 0;
	}
	if (learns_spin(p_options, p_grants)) {
		return std::min(ServoOptions::UNHELD_SPIN_NS,
				wake_ahead_cap_ns(p_options.rate_hz, p_grants.realtime_kit.rttime_usec));
	}
	int64_t spin_ns = p_options.spin_ns;
	if (spin_ns == ServoOptions::SPIN_AUTO) {
		spin_ns = is_realtime_kind(p_grants.kind) ? ServoOptions::DEFAULT_SPIN_NS : 0;
	}
	return std::clamp<int64_t>(spin_ns, 0, max_spin_ns(p_options.rate_hz));
}

Status ServoLoop::start(HapticDevice *p_device, const ServoOptions &p_options) {
	if (state() == ServoState::RUNNING) {
		return Status::error(StatusCode::INVALID_STATE, "the servo is already running");
	}
	const int64_t max_spin = max_spin_ns(p_options.rate_hz);
	if (p_options.spin_ns != ServoOptions::SPIN_AUTO && (p_options.spin_ns < 0 || p_options.spin_ns > max_spin)) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"spin_ns must be in [0, %lld] (half a period) or SPIN_AUTO, got %lld",
				static_cast<long long>(max_spin), static_cast<long long>(p_options.spin_ns));
	}
	stop(); // Joins a thread that ended on a fault.
	device_ = p_device;
	options_ = p_options;
	const int64_t period_ns = std::llround(1e9 / options_.rate_hz);
	pipeline_.begin_session(p_device, static_cast<double>(period_ns) * S_PER_NS);
	channels_.stats.reset(options_.rate_hz);
	stop_requested_.store(false, std::memory_order_relaxed);
	fault_.store(DeviceIo::OK, std::memory_order_relaxed);
	grants_published_.store(false, std::memory_order_relaxed);
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
	// The name top, ps -L and /proc/<pid>/task/*/comm show (15 characters at most).
	set_current_thread_name(SERVO_THREAD_NAME);
	grants_ = apply_realtime_request(options_.realtime);
	int64_t spin_ns = effective_spin_ns(options_, grants_);
	learns_spin_ = learns_spin(options_, grants_);
	wake_ahead_.reset(spin_ns, wake_ahead_cap_ns(options_.rate_hz, grants_.realtime_kit.rttime_usec));
	spin_ns_.store(spin_ns, std::memory_order_relaxed);
	grants_published_.store(true, std::memory_order_release);

	const int64_t period_ns = std::llround(1e9 / options_.rate_hz);
	const double dt_s = static_cast<double>(period_ns) * S_PER_NS;
	const bool naive = options_.scheduling == LoopScheduling::NAIVE_SLEEP;
	int64_t deadline_ns = monotonic_now_ns() + period_ns;
	int64_t previous_wake_ns = -1;
	int64_t slept_at_ns = monotonic_now_ns();
	uint64_t tick_index = 0;
	DeviceIo io = DeviceIo::OK;

	while (!stop_requested_.load(std::memory_order_acquire)) {
		if (naive) {
			sleep_for_ns(period_ns);
		} else {
			const int64_t slept_until_ns = sleep_then_spin_until_ns(deadline_ns, spin_ns);
			if (learns_spin_ && wake_ahead_.observe(slept_at_ns, deadline_ns - spin_ns, slept_until_ns)) {
				spin_ns = wake_ahead_.ahead_ns();
				spin_ns_.store(spin_ns, std::memory_order_relaxed);
			}
		}
		const int64_t wake_ns = monotonic_now_ns();
		if (tick_index++ % CPU_SAMPLE_TICKS == 0) {
			channels_.stats.record_thread_cpu(static_cast<double>(wake_ns) * S_PER_NS,
					static_cast<double>(thread_cpu_time_ns()) * S_PER_NS);
		}
		io = pipeline_.tick(dt_s);
		const int64_t end_ns = monotonic_now_ns();
		slept_at_ns = end_ns;

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

	channels_.stats.record_thread_cpu(static_cast<double>(monotonic_now_ns()) * S_PER_NS,
			static_cast<double>(thread_cpu_time_ns()) * S_PER_NS);
	// Zero force before the thread ends, whatever ended it. Harmless if the device is gone.
	device_->write_zero();
	release_realtime_grants(grants_);
	fault_.store(io, std::memory_order_release);
	state_.store(io == DeviceIo::OK ? ServoState::STOPPED : ServoState::FAULTED, std::memory_order_release);
}

} // namespace haptics
