#pragma once

// The Falcon's USB side is an FTDI FT232 serial bridge (docs/devices/falcon.md, "USB
// identity"): the firmware loader and the I/O loop talk to it with FTDI vendor requests
// ("FTDI vendor requests") and read bulk-IN packets that each begin with two FTDI status
// bytes ("Status bytes on every IN packet"). This file holds those facts as named constants
// and the two small computations on them: the FT232BM/R baud divisor encoding ("Baud divisor
// encoding") and stripping the status bytes.
//
// Sources: docs/devices/falcon.md [FTDI ftdi.h / ftdi.c, FTDI-K, NIF FalconCommLibUSB.cpp].

#include "devices/usb/usb_transport.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace haptics::falcon {

// --- Identity and endpoints (docs/devices/falcon.md, "USB identity") --------------------------
inline constexpr uint16_t FALCON_VENDOR_ID = 0x0403; // FTDI's VID.
inline constexpr uint16_t FALCON_PRODUCT_ID = 0xCB48;
inline constexpr int32_t FALCON_INTERFACE = 0;
inline constexpr uint8_t FALCON_ENDPOINT_OUT = 0x02;
inline constexpr uint8_t FALCON_ENDPOINT_IN = 0x81;
// Every IN read asks for exactly one full-speed packet: NIF warns that other sizes break
// libusb or macOS (docs/devices/falcon.md, "USB identity").
inline constexpr int32_t FTDI_PACKET_SIZE = 64;
inline constexpr int32_t FTDI_STATUS_BYTES = 2;
inline constexpr uint32_t FTDI_CONTROL_TIMEOUT_MS = 1000;

// --- Vendor requests (docs/devices/falcon.md): bmRequestType 0x40, no data stage, wIndex 0 -----
inline constexpr uint8_t FTDI_REQUEST_RESET = 0x00; // wValue: 0 reset, 1 purge RX, 2 purge TX.
inline constexpr uint8_t FTDI_REQUEST_MODEM_CTRL = 0x01;
inline constexpr uint8_t FTDI_REQUEST_SET_FLOW_CTRL = 0x02;
inline constexpr uint8_t FTDI_REQUEST_SET_BAUD_RATE = 0x03;
inline constexpr uint8_t FTDI_REQUEST_SET_DATA = 0x04;
inline constexpr uint8_t FTDI_REQUEST_SET_LATENCY_TIMER = 0x09;

inline constexpr uint16_t FTDI_PURGE_RX = 0x0001;
inline constexpr uint16_t FTDI_PURGE_TX = 0x0002;
inline constexpr uint16_t FTDI_DTR_HIGH = 0x0101; // High byte: which line is set; low: level.
inline constexpr uint16_t FTDI_DTR_LOW = 0x0100;
inline constexpr uint16_t FTDI_RTS_HIGH = 0x0202;
inline constexpr uint16_t FTDI_RTS_LOW = 0x0200;
inline constexpr uint16_t FTDI_FLOW_NONE = 0x0000;
inline constexpr uint16_t FTDI_DATA_8N1 = 0x0008; // 8 data bits, parity none << 8, 1 stop << 11.

// Latency timer: how long the chip holds a partly filled IN packet. 16 ms while loading the
// firmware ("otherwise firmware checks tend to always fail"), 1 ms for the 1 kHz loop.
inline constexpr uint16_t FTDI_LATENCY_FIRMWARE_MS = 16;
inline constexpr uint16_t FTDI_LATENCY_NORMAL_MS = 1;

// The three baud settings NIF sends (docs/devices/falcon.md, "Baud divisor encoding"), as wValue/wIndex of SET_BAUD_RATE.
struct FtdiBaud {
	uint16_t value = 0;
	uint16_t index = 0;
	constexpr bool operator==(const FtdiBaud &) const = default;
};
inline constexpr FtdiBaud FTDI_BAUD_BOOTSTRAP{ 0x4138, 0 }; // 9600 Bd exactly: 312 + 4/8.
inline constexpr FtdiBaud FTDI_BAUD_FIRMWARE_UPLOAD{ 0x0015, 0 }; // Divisor 21: 142 857 Bd ("140000").
inline constexpr FtdiBaud FTDI_BAUD_NORMAL{ 0x0002, 0 }; // Divisor 2: 1.5 MBd.

// One vendor OUT request without a data stage.
struct FtdiRequest {
	uint8_t request = 0;
	uint16_t value = 0;
	uint16_t index = 0;
};

// Sends p_request (bmRequestType 0x40) with the control timeout.
usb::UsbTransfer ftdi_send(usb::UsbTransport &r_transport, const FtdiRequest &p_request);

// FT232BM/R divisor encoding of p_baud (docs/devices/falcon.md: 3 MHz base, 1/8 steps, fraction code in
// wValue bits 14-15 and wIndex bit 0; 3 M and 2 M Bd are special codes). r_actual_baud is
// the rate the chip will really run at. Errors for p_baud outside [184, 3 000 000].
Status ftdi_encode_baud(int32_t p_baud, FtdiBaud &r_baud, double &r_actual_baud);
// The rate an encoded setting runs at (the inverse, for checking NIF's constants).
double ftdi_decoded_baud(const FtdiBaud &p_baud);

// Copies the payload of a bulk-IN transfer of p_length bytes, received into p_transfer, to
// r_payload: every 64-byte packet of it starts with two status bytes (modem, line status),
// which are dropped; a trailing packet shorter than two bytes is malformed and dropped too.
// Returns the payload length (<= p_capacity; bytes that do not fit are dropped and counted
// in r_overflow, if given). A p_length past the end of p_transfer is clamped to it: the
// length comes from the transport, the buffer's size from us.
size_t ftdi_strip_status(std::span<const uint8_t> p_transfer, size_t p_length, uint8_t *r_payload, size_t p_capacity,
		size_t *r_overflow = nullptr);

} // namespace haptics::falcon
