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

} // namespace haptics::usb
