#include "devices/falcon/falcon_ftdi.h"

#include <cmath>

namespace haptics::falcon {

namespace {

constexpr double FTDI_BASE_CLOCK_HZ = 3000000.0; // 48 MHz / 16 (FT232BM/R).
// Eighths of the divisor -> 3-bit code (docs/devices/falcon.md, "Baud divisor encoding"); the code's bits 0-1 go to wValue 14-15, bit 2
// to wIndex bit 0.
constexpr uint32_t FRACTION_CODE[8] = { 0, 3, 2, 4, 1, 5, 6, 7 };
constexpr uint32_t MAX_DIVISOR_EIGHTHS = 0x1FFFF; // 14-bit integer part + 3-bit fraction.

} // namespace

usb::UsbTransfer ftdi_send(usb::UsbTransport &r_transport, const FtdiRequest &p_request) {
	return r_transport.control_transfer(usb::USB_REQUEST_TYPE_VENDOR_OUT, p_request.request, p_request.value,
			p_request.index, nullptr, 0, FTDI_CONTROL_TIMEOUT_MS);
}

Status ftdi_encode_baud(int32_t p_baud, FtdiBaud &r_baud, double &r_actual_baud) {
	// The slowest rate the 17-bit divisor reaches is 3 MHz / 16383.875 ~= 183.1 Bd.
	if (p_baud < 184 || p_baud > 3000000) {
		return Status::error(StatusCode::OUT_OF_RANGE, "FTDI baud rate must be in [184, 3000000] (got %d)", p_baud);
	}
	uint32_t encoded = 0;
	if (p_baud >= 3000000) {
		encoded = 0; // Special: 3 MBd.
		r_actual_baud = 3000000.0;
	} else if (p_baud >= 2000000) {
		encoded = 1; // Special: 2 MBd.
		r_actual_baud = 2000000.0;
	} else {
		// Round to the nearest eighth; a divisor below 2 cannot be expressed with a fraction.
		uint32_t eighths = static_cast<uint32_t>(std::lround(FTDI_BASE_CLOCK_HZ * 8.0 / p_baud));
		eighths = eighths < 16 ? 16 : (eighths > MAX_DIVISOR_EIGHTHS ? MAX_DIVISOR_EIGHTHS : eighths);
		encoded = (eighths >> 3) | (FRACTION_CODE[eighths & 7] << 14);
		r_actual_baud = FTDI_BASE_CLOCK_HZ * 8.0 / eighths;
	}
	r_baud = FtdiBaud{ static_cast<uint16_t>(encoded & 0xFFFF), static_cast<uint16_t>(encoded >> 16) };
	return Status::success();
}

double ftdi_decoded_baud(const FtdiBaud &p_baud) {
	const uint32_t encoded = p_baud.value | (static_cast<uint32_t>(p_baud.index & 1) << 16);
	const uint32_t integer = encoded & 0x3FFF;
	const uint32_t code = encoded >> 14;
	uint32_t eighths = 0;
	for (uint32_t e = 0; e < 8; ++e) {
		if (FRACTION_CODE[e] == code) {
			eighths = e;
		}
	}
	if (integer == 0 && eighths == 0) {
		return 3000000.0;
	}
	if (integer == 1 && eighths == 0) {
		return 2000000.0;
	}
	return FTDI_BASE_CLOCK_HZ * 8.0 / static_cast<double>(integer * 8 + eighths);
}

size_t ftdi_strip_status(std::span<const uint8_t> p_transfer, size_t p_length, uint8_t *r_payload, size_t p_capacity,
		size_t *r_overflow) {
	const size_t length = p_length < p_transfer.size() ? p_length : p_transfer.size();
	size_t written = 0;
	size_t overflow = 0;
	for (size_t packet = 0; packet < length; packet += FTDI_PACKET_SIZE) {
		const size_t end = packet + FTDI_PACKET_SIZE < length ? packet + FTDI_PACKET_SIZE : length;
		for (size_t i = packet + FTDI_STATUS_BYTES; i < end; ++i) {
			if (written < p_capacity) {
				r_payload[written++] = p_transfer[i];
			} else {
				++overflow;
			}
		}
	}
	if (r_overflow) {
		*r_overflow = overflow;
	}
	return written;
}

} // namespace haptics::falcon
