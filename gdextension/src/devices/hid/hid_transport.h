#pragma once

// A HID device as a backend talks to it: the hidapi calls a protocol needs, behind an
// interface so the same protocol code runs over hidapi (hidapi_transport.h) and over a
// scripted firmware model in tests, the benchmark and the game's "scripted:" devices.
//
// Buffers are hidapi's: byte 0 is the report ID (0 when the device uses no report IDs),
// lengths include that byte. Failures say whether the device is gone (DISCONNECTED: the
// player unplugged it) or something else failed (FAILED), and last_error() says what in one
// sentence. The report calls may run on a device I/O thread: implementations must not
// allocate on success paths.

#include "core/base/status.h"
#include "core/device/device.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace haptics::hid {

class HidTransport {
public:
	virtual ~HidTransport() = default;

	virtual Status open() = 0;
	// Idempotent.
	virtual void close() = 0;
	virtual bool is_open() const = 0;
	// The device's report descriptor, at most MAX_DESCRIPTOR_BYTES.
	virtual Status report_descriptor(std::vector<uint8_t> &r_bytes) = 0;

	// An Output report (interrupt OUT, or SET_REPORT when the device has no OUT endpoint).
	virtual DeviceIo write_output(std::span<const uint8_t> p_report) = 0;
	// SET_REPORT(Feature).
	virtual DeviceIo send_feature(std::span<const uint8_t> p_report) = 0;
	// GET_REPORT(Feature) of the ID in p_buffer[0]; r_length counts the ID byte.
	virtual DeviceIo get_feature(std::span<uint8_t> p_buffer, size_t &r_length) = 0;
	// The next Input report if one is waiting, without blocking; r_length = 0 when none.
	virtual DeviceIo read_input(std::span<uint8_t> p_buffer, size_t &r_length) = 0;

	// Why the last failed call failed; "" when none did.
	virtual const char *last_error() const = 0;
	// After a failure whose status is already published: clears what the failure found
	// halted, if anything (a stalled endpoint), and says in last_error() how that went. True
	// when there was something to clear. Slow (a bus reset), so it comes after the status.
	virtual bool clear_halt() { return false; }
};

} // namespace haptics::hid
