#include "devices/usb/usb_transport.h"

namespace haptics::usb {

const char *usb_result_name(UsbResult p_result) {
	switch (p_result) {
		case UsbResult::OK:
			return "LIBUSB_SUCCESS";
		case UsbResult::IO:
			return "LIBUSB_ERROR_IO";
		case UsbResult::INVALID_PARAM:
			return "LIBUSB_ERROR_INVALID_PARAM";
		case UsbResult::ACCESS:
			return "LIBUSB_ERROR_ACCESS";
		case UsbResult::NO_DEVICE:
			return "LIBUSB_ERROR_NO_DEVICE";
		case UsbResult::NOT_FOUND:
			return "LIBUSB_ERROR_NOT_FOUND";
		case UsbResult::BUSY:
			return "LIBUSB_ERROR_BUSY";
		case UsbResult::TIMEOUT:
			return "LIBUSB_ERROR_TIMEOUT";
		case UsbResult::OVERFLOW:
			return "LIBUSB_ERROR_OVERFLOW";
		case UsbResult::PIPE:
			return "LIBUSB_ERROR_PIPE";
		case UsbResult::INTERRUPTED:
			return "LIBUSB_ERROR_INTERRUPTED";
		case UsbResult::NO_MEM:
			return "LIBUSB_ERROR_NO_MEM";
		case UsbResult::NOT_SUPPORTED:
			return "LIBUSB_ERROR_NOT_SUPPORTED";
		case UsbResult::OTHER:
			break;
	}
	return "LIBUSB_ERROR_OTHER";
}

DeviceIo usb_result_io(UsbResult p_result) {
	switch (p_result) {
		case UsbResult::OK:
			return DeviceIo::OK;
		case UsbResult::NO_DEVICE:
			return DeviceIo::DISCONNECTED;
		default:
			return DeviceIo::FAILED;
	}
}

UsbTransfer bounded_transfer(const UsbTransfer &p_transfer, int32_t p_capacity) {
	const int32_t capacity = p_capacity > 0 ? p_capacity : 0;
	if (p_transfer.transferred > capacity) {
		return { UsbResult::OVERFLOW, 0 };
	}
	if (p_transfer.transferred < 0) {
		return { UsbResult::OTHER, 0 };
	}
	return p_transfer;
}

UsbTransfer UsbTransport::control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index,
		uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms) {
	return bounded_transfer(raw_control_transfer(p_request_type, p_request, p_value, p_index, p_data, p_length, p_timeout_ms),
			p_data != nullptr ? p_length : 0);
}

UsbTransfer UsbTransport::bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length, uint32_t p_timeout_ms) {
	return bounded_transfer(raw_bulk_write(p_endpoint, p_bytes, p_length, p_timeout_ms), p_bytes != nullptr ? p_length : 0);
}

UsbTransfer UsbTransport::bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms) {
	return bounded_transfer(raw_bulk_read(p_endpoint, r_buffer, p_length, p_timeout_ms), r_buffer != nullptr ? p_length : 0);
}

} // namespace haptics::usb
