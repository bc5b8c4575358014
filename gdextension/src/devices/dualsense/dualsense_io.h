#pragma once

// The DualSense's I/O cycle, run by the device's DeviceIoThread (device_io_thread.h) at the
// pad's rate: take the newest servo command, let the OutputPlanner decide whether the pad
// must be told something (dualsense_mapping.h), encode and write that report, drain the
// queued input reports (at most MAX_READS_PER_CYCLE, keeping the newest good one), publish
// the stick and buttons. No allocation, lock or logging: only fixed buffers, atomics and the
// transport's calls.
//
// The impact envelope needs every servo tick, not just the one the cycle happens to see:
// the servo side calls offer_impact() each tick (an atomic max), and the cycle takes and
// clears the peak.
//
// On a failed write or read the cycle records the reason in the exchange (DISCONNECTED when
// the pad is gone, FAILED otherwise); after a FAILED it still tries one "off" report, so a
// pad that is there but misbehaving is not left rumbling. io_stop() writes the off report
// (motors 0, both triggers 0x05, lightbar idle, player LEDs off).

#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"
#include "devices/dualsense/dualsense_mapping.h"
#include "devices/dualsense/dualsense_report.h"
#include "devices/dualsense/dualsense_transport.h"

#include <atomic>
#include <cstdint>

namespace haptics::dualsense {

struct DualSenseIoStats {
	uint64_t reports_sent = 0;
	uint64_t bytes_sent = 0;
	uint64_t input_reports = 0; // Decoded.
	uint64_t input_ignored = 0; // Garbled, wrong size, bad CRC, unknown ID.
	uint64_t simple_reports = 0; // BT before the switch to full reports.
};

class DualSenseIo final : public DeviceIoWorker {
public:
	static constexpr int MAX_READS_PER_CYCLE = 16;
	static constexpr size_t INPUT_BUFFER_SIZE = 128; // Larger than any report: no silent truncation.

	// p_transport: the device's; never null once begin() was called.
	DualSenseIo(DualSenseTransport *p_transport, const MappingConfig &p_mapping, double p_stick_radius_m);

	// Game thread, before the I/O thread starts: the link's framing and the rumble recipe;
	// the next cycle re-sends everything; the BT sequence restarts at 0.
	void begin(Bus p_bus, RumbleRecipe p_recipe);

	DeviceIo io_cycle(DeviceExchange &r_exchange, double p_dt_s) override;
	void io_stop() override;

	// Servo thread, every tick.
	void offer_impact(const Vec3 &p_impact_n);

	// Encodes p_state for p_fields in this link's framing and writes it (the thread that
	// owns the transport at the time).
	TransportIo send(const OutputState &p_state, uint32_t p_fields);
	TransportIo send_off();
	// The report send() would write, without writing it or advancing the BT sequence.
	void encode(const OutputState &p_state, uint32_t p_fields, OutputReport &r_report) const;

	DualSenseIoStats stats() const;
	const OutputPlanner &planner() const { return planner_; }

private:
	DeviceIo fail(DeviceExchange &r_exchange, TransportIo p_io, const char *p_what);

	DualSenseTransport *transport_;
	double stick_radius_m_;
	OutputPlanner planner_;
	Bus bus_ = Bus::USB;
	RumbleRecipe recipe_ = RumbleRecipe::IMPROVED;
	uint8_t bt_sequence_ = 0;
	std::atomic<double> impact_peak_n_{ 0.0 };
	DeviceState state_;
	OutputReport report_;
	uint8_t input_[INPUT_BUFFER_SIZE] = {};
	std::atomic<uint64_t> reports_sent_{ 0 };
	std::atomic<uint64_t> bytes_sent_{ 0 };
	std::atomic<uint64_t> input_reports_{ 0 };
	std::atomic<uint64_t> input_ignored_{ 0 };
	std::atomic<uint64_t> simple_reports_{ 0 };
};

} // namespace haptics::dualsense
