#include "devices/device_exchange.h"

#include <cstdio>

namespace haptics {

DeviceIo DeviceExchange::read_state(DeviceState &r_state) const {
	const DeviceIo io = io_.load(std::memory_order_acquire);
	if (io != DeviceIo::OK) {
		return io;
	}
	// A read racing a publish keeps the previous copy: one tick of a 1 ms old position.
	DeviceState state;
	if (state_.try_load(state)) {
		last_state_ = state;
	}
	r_state = last_state_;
	return DeviceIo::OK;
}

DeviceIo DeviceExchange::write_command(const ForceCommand &p_command) {
	const DeviceIo io = io_.load(std::memory_order_acquire);
	if (io != DeviceIo::OK) {
		return io;
	}
	command_.store(StampedCommand{ p_command, monotonic_now_ns() });
	return DeviceIo::OK;
}

void DeviceExchange::publish_state(const DeviceState &p_state) {
	state_.store(p_state);
}

ForceCommand DeviceExchange::latest_command() {
	const StampedCommand stamped = command_.load();
	if (stamped.written_ns != 0) {
		const double age_s = static_cast<double>(monotonic_now_ns() - stamped.written_ns) * 1e-9;
		// One I/O thread writes these: load + store is enough.
		commands_sent_.fetch_add(1, std::memory_order_relaxed);
		age_sum_s_.store(age_sum_s_.load(std::memory_order_relaxed) + age_s, std::memory_order_relaxed);
		if (age_s > age_max_s_.load(std::memory_order_relaxed)) {
			age_max_s_.store(age_s, std::memory_order_relaxed);
		}
	}
	return stamped.command;
}

void DeviceExchange::fail(DeviceIo p_io, const char *p_format, ...) {
	DeviceStatus status;
	status.io = p_io == DeviceIo::OK ? DeviceIo::FAILED : p_io;
	va_list args;
	va_start(args, p_format);
	std::vsnprintf(status.reason, DEVICE_REASON_CAPACITY, p_format, args);
	va_end(args);
	status_.store(status);
	io_.store(status.io, std::memory_order_release);
}

void DeviceExchange::record_cycle(double p_cycle_cost_s) {
	cycles_.fetch_add(1, std::memory_order_relaxed);
	if (p_cycle_cost_s > cycle_cost_max_s_.load(std::memory_order_relaxed)) {
		cycle_cost_max_s_.store(p_cycle_cost_s, std::memory_order_relaxed);
	}
}

void DeviceExchange::reset(const DeviceState &p_initial) {
	command_.store(StampedCommand{});
	state_.store(p_initial);
	last_state_ = p_initial;
	status_.store(DeviceStatus{});
	io_.store(DeviceIo::OK, std::memory_order_release);
	transfer_began_ns_.store(0, std::memory_order_release);
	cycles_.store(0, std::memory_order_relaxed);
	commands_sent_.store(0, std::memory_order_relaxed);
	age_sum_s_.store(0.0, std::memory_order_relaxed);
	age_max_s_.store(0.0, std::memory_order_relaxed);
	cycle_cost_max_s_.store(0.0, std::memory_order_relaxed);
}

DeviceStatus DeviceExchange::status(int64_t p_now_ns) const {
	DeviceStatus status = status_.load();
	const int64_t began_ns = transfer_began_ns_.load(std::memory_order_acquire);
	if (status.io != DeviceIo::OK || began_ns == 0) {
		return status;
	}
	const double stuck_s = static_cast<double>(p_now_ns - began_ns) * 1e-9;
	if (stuck_s > OUTPUT_STALL_S) {
		status.output_stuck_s = stuck_s;
		std::snprintf(status.reason, DEVICE_REASON_CAPACITY,
				"the device has taken no output for %.2f s (its endpoint is busy or stalled): it holds the last force it took",
				stuck_s);
	}
	return status;
}

Status DeviceExchange::ready_status(bool p_open, const char *p_name) const {
	if (!p_open) {
		return Status::error(StatusCode::NO_DEVICE, "cannot calibrate '%s': device not open", p_name);
	}
	const DeviceStatus current = status();
	if (current.io != DeviceIo::OK) {
		return Status::error(current.io == DeviceIo::DISCONNECTED ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"cannot calibrate '%s': %s", p_name, current.reason.c_str());
	}
	return Status::success();
}

DeviceIoStats DeviceExchange::stats() const {
	DeviceIoStats stats;
	stats.cycles = cycles_.load(std::memory_order_relaxed);
	stats.commands_sent = commands_sent_.load(std::memory_order_relaxed);
	stats.command_age_mean_s = stats.commands_sent > 0 ? age_sum_s_.load(std::memory_order_relaxed) / static_cast<double>(stats.commands_sent) : 0.0;
	stats.command_age_max_s = age_max_s_.load(std::memory_order_relaxed);
	stats.cycle_cost_max_s = cycle_cost_max_s_.load(std::memory_order_relaxed);
	return stats;
}

} // namespace haptics
