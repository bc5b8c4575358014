#pragma once

// The DualSense backend's own seam to the HID layer: three calls, so the protocol and the
// device are tested against a scripted pad (dev_tools/dualsense/scripted_dualsense.h) and
// run against hidapi (dualsense_hidapi_transport.h) unchanged. Deliberately small and local to this backend
// (the PID backend has its own generic HID transport; the two may be unified later).
//
// Buffers are hidapi's: byte 0 is the report ID. The I/O calls are made by ONE thread at a
// time (the device's I/O thread while it runs, the game thread in open/close) and must not
// allocate on success; error_text() is only meaningful right after a failure.

#include "core/base/status.h"
#include "devices/dualsense/dualsense_bus.h"

#include <cstddef>
#include <cstdint>

namespace haptics::dualsense {

enum class TransportIo : int32_t {
	OK = 0,
	NO_DATA = 1, // Non-blocking read: nothing queued.
	DISCONNECTED = 2, // The pad is gone (unplugged, out of Bluetooth range, powered off).
	FAILED = 3, // Any other error.
};

class DualSenseTransport {
public:
	virtual ~DualSenseTransport() = default;

	// Game thread. DEVICE_DISCONNECTED/NO_DEVICE when the pad is not there, DEVICE_ERROR
	// otherwise (e.g. permissions); the message names the path.
	virtual Status open() = 0;
	// Idempotent.
	virtual void close() = 0;
	virtual bool is_open() const = 0;
	// The link, when the HID layer can tell (hidapi >= 0.13); UNKNOWN otherwise.
	virtual Bus bus() const = 0;

	virtual TransportIo write_output(const uint8_t *p_report, size_t p_size) = 0;
	// Waits up to p_timeout_ms (0: returns NO_DATA at once when nothing is queued). r_size is
	// the report's length, report ID included.
	virtual TransportIo read_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, int p_timeout_ms = 0) = 0;
	// r_buffer[0] is set to p_report_id; r_size counts the ID byte.
	virtual TransportIo get_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size) = 0;

	// Why the last call failed, one phrase (e.g. hidapi's "No such device"); "" if none.
	virtual const char *error_text() const = 0;
	// Where the pad is, for messages (the hidraw path, "scripted USB pad").
	virtual const char *location() const = 0;
};

} // namespace haptics::dualsense
