#include "devices/usb/libusb_transport.h"

#include <libusb.h>

#include <charconv>
#include <chrono>
#include <climits>
#include <cstdio>
#include <thread>

namespace haptics::usb {

namespace {

// How long LibusbTransport::explain() gives the kernel to notice an unplug: 5 x 20 ms.
constexpr int PRESENCE_ATTEMPTS = 5;
constexpr unsigned PRESENCE_TIMEOUT_MS = 20;

bool parse_decimal(std::string_view p_text, int32_t p_max, int32_t &r_value) {
	if (p_text.empty()) {
		return false;
	}
	const char *end = p_text.data() + p_text.size();
	const std::from_chars_result parsed = std::from_chars(p_text.data(), end, r_value, 10);
	return parsed.ec == std::errc() && parsed.ptr == end && r_value >= 0 && r_value <= p_max;
}

bool parse_hex16(std::string_view p_text, uint16_t &r_value) {
	if (p_text.empty() || p_text.size() > 4) {
		return false;
	}
	const char *end = p_text.data() + p_text.size();
	const std::from_chars_result parsed = std::from_chars(p_text.data(), end, r_value, 16);
	return parsed.ec == std::errc() && parsed.ptr == end;
}

bool matches_path(libusb_device *p_device, const UsbPortPath &p_path) {
	if (libusb_get_bus_number(p_device) != p_path.bus) {
		return false;
	}
	if (p_path.address >= 0) {
		return libusb_get_device_address(p_device) == p_path.address;
	}
	uint8_t ports[UsbPortPath::MAX_PORTS] = {};
	const int count = libusb_get_port_numbers(p_device, ports, UsbPortPath::MAX_PORTS);
	if (count != p_path.port_count) {
		return false;
	}
	for (int32_t i = 0; i < count; ++i) {
		if (ports[i] != p_path.ports[i]) {
			return false;
		}
	}
	return true;
}

struct FreeDeviceList {
	libusb_device **list = nullptr;
	~FreeDeviceList() {
		if (list) {
			libusb_free_device_list(list, 1);
		}
	}
};

// Finds the requested device in r_context and opens it. On failure the context is left for
// the caller to exit.
Status open_handle(libusb_context *p_context, const LibusbOpenRequest &p_request, libusb_device_handle *&r_handle,
		UsbResult &r_result) {
	UsbPortPath path;
	const bool by_path = !p_request.path.empty();
	if (by_path) {
		const Status parsed = parse_usb_port_path(p_request.path, path);
		if (!parsed) {
			r_result = UsbResult::INVALID_PARAM;
			return parsed;
		}
	}
	FreeDeviceList devices;
	const ssize_t count = libusb_get_device_list(p_context, &devices.list);
	if (count < 0) {
		r_result = usb_result_from_libusb(static_cast<int>(count));
		return Status::error(StatusCode::NO_DEVICE, "%s: cannot list USB devices (%s)", p_request.label.c_str(),
				usb_result_name(r_result));
	}
	if (count == 0) {
		r_result = UsbResult::NO_DEVICE;
		return Status::error(StatusCode::NO_DEVICE,
				"%s %04x:%04x not present: no USB bus visible (libusb lists no devices; none exposed to this process)",
				p_request.label.c_str(), p_request.vendor_id, p_request.product_id);
	}
	for (ssize_t i = 0; i < count; ++i) {
		libusb_device *device = devices.list[i];
		libusb_device_descriptor descriptor{};
		if (libusb_get_device_descriptor(device, &descriptor) != 0 || descriptor.idVendor != p_request.vendor_id ||
				descriptor.idProduct != p_request.product_id || (by_path && !matches_path(device, path))) {
			continue;
		}
		const int opened = libusb_open(device, &r_handle);
		if (opened != 0) {
			r_result = usb_result_from_libusb(opened);
			return Status::error(r_result == UsbResult::NO_DEVICE ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR,
					"%s %04x:%04x at usb:%s cannot be opened (%s)", p_request.label.c_str(), p_request.vendor_id,
					p_request.product_id, by_path ? p_request.path.c_str() : "any", usb_result_name(r_result));
		}
		r_result = UsbResult::OK;
		return Status::success();
	}
	r_result = UsbResult::NO_DEVICE;
	return Status::error(StatusCode::NO_DEVICE, "%s %04x:%04x not present%s%s (%zd USB devices seen)",
			p_request.label.c_str(), p_request.vendor_id, p_request.product_id, by_path ? " at usb:" : "",
			by_path ? p_request.path.c_str() : "", count);
}

Status init_context(const LibusbOpenRequest &p_request, libusb_context *&r_context, UsbResult &r_result) {
#if LIBUSB_API_VERSION >= 0x0100010A // 1.0.27 deprecates libusb_init().
	const int init = libusb_init_context(&r_context, nullptr, 0);
#else
	const int init = libusb_init(&r_context);
#endif
	if (init != 0) {
		r_context = nullptr;
		r_result = usb_result_from_libusb(init);
		return Status::error(StatusCode::NO_DEVICE, "%s %04x:%04x not present: no USB bus available (libusb_init: %s)",
				p_request.label.c_str(), p_request.vendor_id, p_request.product_id, usb_result_name(r_result));
	}
	return Status::success();
}

} // namespace

UsbResult usb_result_from_libusb(int p_code) {
	if (p_code >= 0) {
		return UsbResult::OK;
	}
	switch (p_code) {
		case LIBUSB_ERROR_IO:
			return UsbResult::IO;
		case LIBUSB_ERROR_INVALID_PARAM:
			return UsbResult::INVALID_PARAM;
		case LIBUSB_ERROR_ACCESS:
			return UsbResult::ACCESS;
		case LIBUSB_ERROR_NO_DEVICE:
			return UsbResult::NO_DEVICE;
		case LIBUSB_ERROR_NOT_FOUND:
			return UsbResult::NOT_FOUND;
		case LIBUSB_ERROR_BUSY:
			return UsbResult::BUSY;
		case LIBUSB_ERROR_TIMEOUT:
			return UsbResult::TIMEOUT;
		case LIBUSB_ERROR_OVERFLOW:
			return UsbResult::OVERFLOW;
		case LIBUSB_ERROR_PIPE:
			return UsbResult::PIPE;
		case LIBUSB_ERROR_INTERRUPTED:
			return UsbResult::INTERRUPTED;
		case LIBUSB_ERROR_NO_MEM:
			return UsbResult::NO_MEM;
		case LIBUSB_ERROR_NOT_SUPPORTED:
			return UsbResult::NOT_SUPPORTED;
		default:
			return UsbResult::OTHER;
	}
}

Status parse_usb_port_path(std::string_view p_text, UsbPortPath &r_path) {
	const auto invalid = [p_text]() {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"USB path '%.*s' is not '<bus>-<port>[.<port>...]', '<bus>-root' or '<bus>-addr<N>'",
				static_cast<int>(p_text.size() > 64 ? 64 : p_text.size()), p_text.data());
	};
	UsbPortPath path;
	const size_t dash = p_text.find('-');
	int32_t bus = 0;
	if (dash == std::string_view::npos || !parse_decimal(p_text.substr(0, dash), 255, bus)) {
		return invalid();
	}
	path.bus = static_cast<uint8_t>(bus);
	std::string_view rest = p_text.substr(dash + 1);
	if (rest == "root") {
		r_path = path;
		return Status::success();
	}
	if (rest.substr(0, 4) == "addr") {
		int32_t address = 0;
		if (!parse_decimal(rest.substr(4), 127, address)) {
			return invalid();
		}
		path.address = address;
		r_path = path;
		return Status::success();
	}
	while (true) {
		const size_t dot = rest.find('.');
		int32_t port = 0;
		if (path.port_count == UsbPortPath::MAX_PORTS || !parse_decimal(rest.substr(0, dot), 255, port)) {
			return invalid();
		}
		path.ports[path.port_count++] = static_cast<uint8_t>(port);
		if (dot == std::string_view::npos) {
			break;
		}
		rest = rest.substr(dot + 1);
	}
	r_path = path;
	return Status::success();
}

Status parse_usb_vid_pid(std::string_view p_text, uint16_t &r_vendor_id, uint16_t &r_product_id) {
	const size_t colon = p_text.find(':');
	uint16_t vendor = 0;
	uint16_t product = 0;
	if (colon == std::string_view::npos || !parse_hex16(p_text.substr(0, colon), vendor) ||
			!parse_hex16(p_text.substr(colon + 1), product)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "USB id '%.*s' is not 'vvvv:pppp' (hex)",
				static_cast<int>(p_text.size() > 32 ? 32 : p_text.size()), p_text.data());
	}
	r_vendor_id = vendor;
	r_product_id = product;
	return Status::success();
}

LibusbTransport::~LibusbTransport() {
	close();
}

void LibusbTransport::close() {
	if (handle_) {
		if (interface_number_ >= 0) {
			libusb_release_interface(handle_, interface_number_);
			interface_number_ = -1;
		}
		libusb_close(handle_);
		handle_ = nullptr;
	}
	if (context_) {
		libusb_exit(context_);
		context_ = nullptr;
	}
}

Status LibusbTransport::open(const LibusbOpenRequest &p_request, std::unique_ptr<LibusbTransport> &r_transport,
		UsbResult *r_result) {
	UsbResult result = UsbResult::OK;
	std::unique_ptr<LibusbTransport> transport(new LibusbTransport());
	Status status = init_context(p_request, transport->context_, result);
	if (status) {
		status = open_handle(transport->context_, p_request, transport->handle_, result);
	}
	if (status) {
		// Only where the OS supports it (Linux); elsewhere NOT_SUPPORTED is expected and harmless.
		libusb_set_auto_detach_kernel_driver(transport->handle_, 1);
		const int claimed = libusb_claim_interface(transport->handle_, p_request.interface_number);
		if (claimed != 0) {
			result = usb_result_from_libusb(claimed);
			status = Status::error(result == UsbResult::NO_DEVICE ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR,
					"%s %04x:%04x: cannot claim interface %d (%s%s)", p_request.label.c_str(), p_request.vendor_id,
					p_request.product_id, p_request.interface_number, usb_result_name(result),
					result == UsbResult::BUSY ? ": another program or a kernel driver holds it" : "");
		} else {
			transport->interface_number_ = p_request.interface_number;
		}
	}
	if (r_result) {
		*r_result = result;
	}
	if (!status) {
		return status; // The destructor closes whatever was opened.
	}
	transport->description_ = "usb:" + (p_request.path.empty() ? std::string("any") : p_request.path);
	r_transport = std::move(transport);
	return Status::success();
}

Status LibusbTransport::check_access(const LibusbOpenRequest &p_request, UsbResult *r_result) {
	UsbResult result = UsbResult::OK;
	LibusbTransport probe;
	Status status = init_context(p_request, probe.context_, result);
	if (status) {
		status = open_handle(probe.context_, p_request, probe.handle_, result);
	}
	if (r_result) {
		*r_result = result;
	}
	return status;
}

UsbTransfer LibusbTransport::raw_control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value,
		uint16_t p_index, uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms) {
	const int done = libusb_control_transfer(handle_, p_request_type, p_request, p_value, p_index, p_data, p_length,
			p_timeout_ms);
	return done >= 0 ? UsbTransfer{ UsbResult::OK, done } : UsbTransfer{ explain(usb_result_from_libusb(done)), 0 };
}

UsbTransfer LibusbTransport::raw_bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length,
		uint32_t p_timeout_ms) {
	int transferred = 0;
	// libusb takes a non-const buffer for both directions; an OUT transfer does not write it.
	const int code = libusb_bulk_transfer(handle_, p_endpoint, const_cast<uint8_t *>(p_bytes), p_length, &transferred,
			p_timeout_ms);
	return { explain(usb_result_from_libusb(code)), transferred };
}

UsbTransfer LibusbTransport::raw_bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms) {
	int transferred = 0;
	const int code = libusb_bulk_transfer(handle_, p_endpoint, r_buffer, p_length, &transferred, p_timeout_ms);
	return { explain(usb_result_from_libusb(code)), transferred };
}

UsbResult LibusbTransport::explain(UsbResult p_result) {
	if (p_result != UsbResult::IO || handle_ == nullptr) {
		return p_result;
	}
	// A transfer the unplug cut short fails with LIBUSB_ERROR_IO (the URB's -EPROTO or
	// -ESHUTDOWN), and the kernel notices the device has gone a few ms later (seen on Linux
	// 6.1 with dummy_hcd: docs/linux-kernel.md): ask the device until it answers or is known gone.
	for (int attempt = 0; attempt < PRESENCE_ATTEMPTS; ++attempt) {
		uint8_t status[2] = {};
		const int done = libusb_control_transfer(handle_, LIBUSB_ENDPOINT_IN, LIBUSB_REQUEST_GET_STATUS, 0, 0, status,
				sizeof(status), PRESENCE_TIMEOUT_MS);
		if (done >= 0) {
			return p_result; // Still there: a real I/O error.
		}
		if (done == LIBUSB_ERROR_NO_DEVICE) {
			return UsbResult::NO_DEVICE;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(PRESENCE_TIMEOUT_MS));
	}
	return p_result;
}

} // namespace haptics::usb
