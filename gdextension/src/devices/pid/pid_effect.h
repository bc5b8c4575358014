#pragma once

// The report sequences of one constant-force effect over a HidTransport, as the Linux
// hid-pidff driver orders them (docs/devices/hid-pid.md, "The kernel's report sequences"), so
// the bytes match its "Expected bytes":
//
//   initialize_device: Device Control Reset, Reset (Linux: "sometimes hid_wait_io isn't
//                      waiting long enough"), Stop All Effects, Enable Actuators; Device Gain.
//   upload:  Create New Effect (feature SET) -> Block Load (feature GET, up to 60 times
//            until Success / Full / Error) -> Set Effect -> Set Constant Force.
//   play:    Effect Operation Start (loop count 1).
//   update:  only what changed, in field units after quantisation: a new level is exactly
//            one Set Constant Force report, a new direction exactly one Set Effect report.
//   stop:    Effect Operation Stop (the loop-count byte keeps its previous value, as Linux).
//   erase:   stop, then Block Free.
//
// The Pool report is never read: AJ's firmware frees every effect when it is
// (docs/devices/hid-pid.md, "AJ's firmware behaviour").
// upload/initialize run at open (feature transfers are slow control transfers); update,
// play and stop run on the device I/O thread and neither allocate nor build a Status.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/hid/hid_transport.h"
#include "devices/pid/pid_layout.h"
#include "devices/pid/pid_protocol.h"

#include <cstdint>

namespace haptics::pid {

struct PidEffectOptions {
	uint32_t block_load_attempts = 60; // K-old/K-new.
	uint32_t block_load_retry_delay_us = 1000; // Between non-answers only.
};

// What update() put on the wire (tests check "exactly one report").
struct PidUpdateResult {
	bool sent_set_effect = false;
	bool sent_set_constant = false;
};

Status send_device_command(hid::HidTransport &r_transport, const PidLayout &p_layout, DeviceCommand p_command);
Status send_device_gain(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_gain);
Status initialize_device(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_gain = 0xFFFF);

class ConstantForceEffect {
public:
	// Allocates the effect on the device and writes its parameters (not yet playing).
	Status upload(hid::HidTransport &r_transport, const PidLayout &p_layout, uint16_t p_direction, int16_t p_level,
			const PidEffectOptions &p_options = {});
	bool uploaded() const { return layout_ != nullptr; }
	uint8_t block_index() const { return block_index_; }

	DeviceIo play(hid::HidTransport &r_transport, uint8_t p_loop_count = 1);
	DeviceIo update(hid::HidTransport &r_transport, uint16_t p_direction, int16_t p_level, PidUpdateResult *r_result = nullptr);
	DeviceIo stop(hid::HidTransport &r_transport);
	// Stop + Block Free; forgets the effect even when the device is gone.
	DeviceIo erase(hid::HidTransport &r_transport);
	// Block Free alone, for an effect already stopped; forgets the effect.
	DeviceIo free_block(hid::HidTransport &r_transport);
	// Forgets the effect without any I/O (the device was reset or unplugged).
	void forget() { layout_ = nullptr; }

	// The last values written, in field units.
	int64_t direction_value() const { return direction_value_; }
	int64_t magnitude_value() const { return magnitude_value_; }
	uint64_t reports_sent() const { return reports_sent_; }
	uint64_t bytes_sent() const { return bytes_sent_; }

private:
	DeviceIo send(hid::HidTransport &r_transport, const PidReport &p_report);

	const PidLayout *layout_ = nullptr;
	uint8_t block_index_ = 0;
	uint8_t loop_count_ = 0;
	int64_t direction_value_ = 0;
	int64_t magnitude_value_ = 0;
	uint64_t reports_sent_ = 0;
	uint64_t bytes_sent_ = 0;
	PidReport scratch_;
};

} // namespace haptics::pid
