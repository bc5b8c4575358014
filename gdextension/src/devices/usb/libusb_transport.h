#pragma once

// UsbTransport on libusb-1.0: opens one device by the path device enumeration reports for
// it (device_enumeration.cpp: "<bus>-<port>.<port>...", "<bus>-root" or "<bus>-addr<N>",
// the sysfs-style port chain that survives re-plugging into the same socket), or by
// VID:PID alone when the path is empty; claims one interface; synchronous transfers.
//
// Every way this can fail on a player's machine gives a Status that says which, with the
// libusb error name: no USB bus at all (a container, a sandbox: libusb_init fails or lists
// nothing), the device not there, no permission for its node (the udev rule), the interface
// held by another program. The raw UsbResult comes back too, for the backend to word the
// advice (the Falcon's probe turns ACCESS into "install the udev rule").
//
// A private libusb context per transport: the game, or another library, may use libusb in
// the same process.

#include "core/base/status.h"
#include "devices/usb/usb_transport.h"

#include <memory>
#include <string>
#include <string_view>

struct libusb_context;
struct libusb_device_handle;

namespace haptics::usb {

struct LibusbOpenRequest {
	std::string path; // As DeviceInfo::path; empty = the first device with the VID:PID.
	uint16_t vendor_id = 0; // Both required: a path alone could name another device after a re-plug.
	uint16_t product_id = 0;
	int32_t interface_number = 0;
	std::string label = "USB device"; // For messages, e.g. "Novint Falcon".
};

// A port path as device enumeration writes it. Parsed so a malformed setting gives an error
// naming it rather than "not present".
struct UsbPortPath {
	static constexpr int32_t MAX_PORTS = 7; // USB allows at most 7 tiers.
	uint8_t bus = 0;
	int32_t port_count = 0; // 0 with !address: the root hub itself ("<bus>-root").
	uint8_t ports[MAX_PORTS] = {};
	int32_t address = -1; // ">= 0": "<bus>-addr<N>" (libusb could not tell the ports).
};

Status parse_usb_port_path(std::string_view p_text, UsbPortPath &r_path);
// "0403:cb48" (hex, either case).
Status parse_usb_vid_pid(std::string_view p_text, uint16_t &r_vendor_id, uint16_t &r_product_id);

class LibusbTransport final : public UsbTransport {
public:
	~LibusbTransport() override;
	LibusbTransport(const LibusbTransport &) = delete;
	LibusbTransport &operator=(const LibusbTransport &) = delete;

	// On failure r_transport stays empty and r_result (optional) says why in libusb's terms.
	static Status open(const LibusbOpenRequest &p_request, std::unique_ptr<LibusbTransport> &r_transport,
			UsbResult *r_result = nullptr);
	// Whether the device can be opened by this process (libusb_open, then closed at once;
	// the interface is not claimed, so a running game keeps its device). For probe().
	static Status check_access(const LibusbOpenRequest &p_request, UsbResult *r_result = nullptr);

	const char *describe() const override { return description_.c_str(); }

private:
	LibusbTransport() = default;
	UsbTransfer raw_control_transfer(uint8_t p_request_type, uint8_t p_request, uint16_t p_value, uint16_t p_index,
			uint8_t *p_data, uint16_t p_length, uint32_t p_timeout_ms) override;
	UsbTransfer raw_bulk_write(uint8_t p_endpoint, const uint8_t *p_bytes, int32_t p_length, uint32_t p_timeout_ms) override;
	UsbTransfer raw_bulk_read(uint8_t p_endpoint, uint8_t *r_buffer, int32_t p_length, uint32_t p_timeout_ms) override;
	void close();
	// p_result, or NO_DEVICE when an I/O error was the device leaving.
	UsbResult explain(UsbResult p_result);

	libusb_context *context_ = nullptr;
	libusb_device_handle *handle_ = nullptr;
	int32_t interface_number_ = -1; // Claimed interface, -1 when none.
	std::string description_;
};

// libusb's error code (LIBUSB_ERROR_*) as a UsbResult; >= 0 is OK.
UsbResult usb_result_from_libusb(int p_code);

} // namespace haptics::usb
