#include "devices/dualsense/dualsense_io.h"

#include <cmath>

namespace haptics::dualsense {

static_assert(std::atomic<double>::is_always_lock_free, "the servo hands the impact peak over lock-free");

DualSenseIo::DualSenseIo(DualSenseTransport *p_transport, const MappingConfig &p_mapping, double p_stick_radius_m) :
		transport_(p_transport), stick_radius_m_(p_stick_radius_m), planner_(p_mapping) {}

void DualSenseIo::begin(Bus p_bus, RumbleRecipe p_recipe) {
	bus_ = p_bus;
	recipe_ = p_recipe;
	bt_sequence_ = 0;
	planner_.reset();
	impact_peak_n_.store(0.0, std::memory_order_relaxed);
	state_ = DeviceState{};
	state_.ready = false; // Until the first input report says where the stick is.
}

void DualSenseIo::offer_impact(const Vec3 &p_impact_n) {
	const double magnitude = length(p_impact_n);
	if (!std::isfinite(magnitude)) {
		return; // The safety stage zeroes non-finite output; nothing to feel.
	}
	double peak = impact_peak_n_.load(std::memory_order_relaxed);
	while (magnitude > peak && !impact_peak_n_.compare_exchange_weak(peak, magnitude, std::memory_order_relaxed)) {
	}
}

void DualSenseIo::encode(const OutputState &p_state, uint32_t p_fields, OutputReport &r_report) const {
	uint8_t block[COMMON_SIZE];
	encode_common(p_state, p_fields, recipe_, block);
	if (bus_ == Bus::BLUETOOTH) {
		wrap_bt_report(block, bt_sequence_, r_report);
	} else {
		wrap_usb_report(block, r_report);
	}
}

TransportIo DualSenseIo::send(const OutputState &p_state, uint32_t p_fields) {
	encode(p_state, p_fields, report_);
	if (bus_ == Bus::BLUETOOTH) {
		bt_sequence_ = static_cast<uint8_t>((bt_sequence_ + 1) & 0x0F);
	}
	const TransportIo io = transport_->write_output(report_.bytes, report_.size);
	if (io == TransportIo::OK) {
		reports_sent_.fetch_add(1, std::memory_order_relaxed);
		bytes_sent_.fetch_add(report_.size, std::memory_order_relaxed);
	}
	return io;
}

TransportIo DualSenseIo::send_off() {
	// Stops our rumble if the pad holds one; a rumble of Godot's SDL is not ours to end.
	return send(OutputPlanner::off_state(), planner_.rumble_on_pad() ? FIELDS_STATE : FIELDS_HELD);
}

DeviceIo DualSenseIo::fail(DeviceExchange &r_exchange, TransportIo p_io, const char *p_what) {
	if (p_io == TransportIo::DISCONNECTED) {
		r_exchange.fail(DeviceIo::DISCONNECTED, "DualSense disconnected (%s, %s): %s", transport_->location(), p_what,
				transport_->error_text());
		return DeviceIo::DISCONNECTED;
	}
	r_exchange.fail(DeviceIo::FAILED, "DualSense %s failed (%s): %s", p_what, transport_->location(), transport_->error_text());
	send_off(); // Best effort: the pad may still be listening.
	return DeviceIo::FAILED;
}

DeviceIo DualSenseIo::io_cycle(DeviceExchange &r_exchange, double p_dt_s) {
	const ForceCommand command = r_exchange.latest_command();
	const double peak_n = impact_peak_n_.exchange(0.0, std::memory_order_relaxed);
	OutputState next;
	const uint32_t fields = planner_.plan(command, peak_n, p_dt_s, next);
	if (fields != 0) {
		const TransportIo written = send(next, fields);
		if (written != TransportIo::OK) {
			return fail(r_exchange, written, "output report");
		}
	}

	bool fresh = false;
	PadInput newest;
	for (int i = 0; i < MAX_READS_PER_CYCLE; ++i) {
		size_t size = 0;
		const TransportIo read = transport_->read_input(input_, sizeof(input_), size, 0);
		if (read == TransportIo::NO_DATA) {
			break;
		}
		if (read != TransportIo::OK) {
			return fail(r_exchange, read, "input report");
		}
		PadInput decoded;
		switch (decode_input_report(input_, size, bus_, decoded)) {
			case InputDecode::OK:
				newest = decoded;
				fresh = true;
				input_reports_.fetch_add(1, std::memory_order_relaxed);
				break;
			case InputDecode::SIMPLE_MODE:
				simple_reports_.fetch_add(1, std::memory_order_relaxed);
				break;
			default:
				input_ignored_.fetch_add(1, std::memory_order_relaxed);
				break;
		}
	}
	if (fresh) {
		state_.position_m = stick_position_m(newest, stick_radius_m_);
		state_.buttons = newest.buttons;
		state_.ready = true;
		r_exchange.publish_state(state_);
	}
	return DeviceIo::OK;
}

void DualSenseIo::io_stop() {
	send_off(); // Nothing to report to: the session is ending either way.
}

DualSenseIoStats DualSenseIo::stats() const {
	DualSenseIoStats stats;
	stats.reports_sent = reports_sent_.load(std::memory_order_relaxed);
	stats.bytes_sent = bytes_sent_.load(std::memory_order_relaxed);
	stats.input_reports = input_reports_.load(std::memory_order_relaxed);
	stats.input_ignored = input_ignored_.load(std::memory_order_relaxed);
	stats.simple_reports = simple_reports_.load(std::memory_order_relaxed);
	return stats;
}

} // namespace haptics::dualsense
