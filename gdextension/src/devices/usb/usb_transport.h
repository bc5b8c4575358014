#pragma once

// The seam between a USB device's protocol code and the bus: the three kinds of transfer a
// vendor-class device such as the Falcon's FTDI bridge needs, synchronous, with explicit
// timeouts. libusb implements it on real hardware (libusb_transport.h); each backend's
// scripted device implements it in tests, the benchmark and the headless game test, so the
// protocol above it runs unchanged against both.
//
// Results are this header's own codes, not libusb's, so that protocol code and scripted
// transports need no libusb header; libusb_transport.cpp maps libusb's errors onto them
// and usb_result_name() spells them as libusb does ("LIBUSB_ERROR_NO_DEVICE"), which is
// what a user searching the web for the message will find.
//
// Threading: one thread at a time per transport (open on the game thread, then the device's
// I/O thread only).

#include "core/device/device.h"

#include <cstdint>

namespace haptics::usb {

enum class UsbResult : int32_t {
	OK = 0,
	IO, // Any other bus error.
	INVALID_PARAM,
	ACCESS, // No permission for the device node: the udev rule is missing.
	NO_DEVICE, // Unplugged (or never there).
	NOT_FOUND,
	BUSY, // Another process or a kernel driver holds the interface.
	TIMEOUT,
	OVERFLOW, // The device sent more than the buffer holds.
	PIPE, // Endpoint stalled / request not supported.
	INTERRUPTED,
	NO_MEM,
	NOT_SUPPORTED,
	OTHER,
};

// "LIBUSB_SUCCESS", "LIBUSB_ERROR_NO_DEVICE", ...: libusb's own names.
const char *usb_result_name(UsbResult p_result);

// What a failed transfer means for rendering: an unplugged device is DISCONNECTED (the HUD
// says "reconnect"), everything else FAILED.
DeviceIo usb_result_io(UsbResult p_result);

struct UsbTransfer {
	UsbResult result = UsbResult::OK;
	int32_t transferred = 0; // Bytes moved; may be > 0 with TIMEOUT (a partial transfer).

	bool ok() const { return result == UsbResult::OK; }
};

// bmRequestType bits (USB 2.0 §9.3) the backends use.
inline constexpr uint8_t USB_REQUEST_TYPE_VENDOR_OUT = 0x40; // Vendor, host to device, device.
inline constexpr uint8_t USB_REQUEST_TYPE_VENDOR_IN = 0xC0; // Vendor, device to host, device.
inline constexpr uint8_t USB_ENDPOINT_IN = 0x80;

// p_transfer when its count lies in [0, p_capacity]; otherwise nothing was transferred as
// far as the caller is concerned: OVERFLOW for a count past the buffer (libusb's word for a
// device sending more than asked for), OTHER for a negative one.
UsbTransfer bounded_transfer(const UsbTransfer &p_transfer, int32_t p_capacity);

class UsbTransport {
public:
	virtual ~UsbTransport() = default;

	// What callers use. Each returns the implementation's result through bounded_transfer()
	// with its own buffer length, so a transport that reports more bytes than the buffer
	// holds (a driver bug, a broken fake) never makes protocol code read or copy past it.
	// p_data/p_length: the data stage (read into for IN requests, sent for OUT); nullptr/0
	// for requests without one.
	UsbTransfer control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index,
			uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms);
	UsbTransfer bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length, uint32_t p_timeout_ms);
	// Reads at most p_length bytes (one or more max-size packets) into r_buffer.
	UsbTransfer bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms);
	// Human-readable place of the device, for messages ("usb:1-4.2", "scripted Falcon").
	virtual const char *describe() const = 0;

private:
	// The implementations' side, same arguments; their counts are not trusted.
	virtual UsbTransfer raw_control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index,
			uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms) = 0;
	virtual UsbTransfer raw_bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length, uint32_t p_timeout_ms) = 0;
	virtual UsbTransfer raw_bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms) = 0;
};

} // namespace haptics::usb
