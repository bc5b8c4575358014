// The real libusb transport and the backend's entry points on this machine, which has no
// Falcon (and in CI no USB bus at all): every path must end in a clean, explained Status.

#include "devices/falcon/falcon_backend.h"
#include "devices/falcon/falcon_ftdi.h"
#include "devices/usb/libusb_transport.h"

#include <doctest/doctest.h>

#include <cstring>
#include <memory>

using namespace haptics;
using namespace haptics::falcon;

namespace {

DeviceInfo falcon_info(const char *p_path) {
	DeviceInfo info;
	info.id = std::string("usb:") + p_path;
	info.backend = BACKEND_LIBUSB;
	info.vendor_id = 0x0403;
	info.product_id = 0xCB48;
	info.path = p_path;
	return info;
}

} // namespace

TEST_CASE("falcon libusb: opening 0403:cb48 without a Falcon is a clean NO_DEVICE 'not present'") {
	usb::LibusbOpenRequest request;
	request.vendor_id = FALCON_VENDOR_ID;
	request.product_id = FALCON_PRODUCT_ID;
	request.label = "Novint Falcon";
	std::unique_ptr<usb::LibusbTransport> transport;
	usb::UsbResult result = usb::UsbResult::OK;
	const Status status = usb::LibusbTransport::open(request, transport, &result);
	MESSAGE("libusb here: " << std::string(status.message()));
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(status.message(), "Novint Falcon 0403:cb48 not present") != nullptr);
	CHECK(transport == nullptr);
	CHECK(result != usb::UsbResult::OK);

	request.path = "1-4.2";
	CHECK(usb::LibusbTransport::open(request, transport, &result).code() == StatusCode::NO_DEVICE);
	CHECK(usb::LibusbTransport::check_access(request, &result).code() == StatusCode::NO_DEVICE);
}

TEST_CASE("falcon libusb: a malformed path names itself (when a bus exists) or reports the missing bus") {
	usb::LibusbOpenRequest request;
	request.vendor_id = FALCON_VENDOR_ID;
	request.product_id = FALCON_PRODUCT_ID;
	request.path = "nonsense";
	std::unique_ptr<usb::LibusbTransport> transport;
	const Status status = usb::LibusbTransport::open(request, transport);
	CHECK_FALSE(status.ok());
	const bool names_path = std::strstr(status.message(), "'nonsense'") != nullptr;
	const bool no_bus = std::strstr(status.message(), "not present") != nullptr;
	CHECK((names_path || no_bus));
}

TEST_CASE("falcon backend: probe handles only libusb 0403:cb48 and explains why it cannot open") {
	DeviceInfo other = falcon_info("1-1");
	other.product_id = 0x6001; // A plain FT232.
	CHECK_FALSE(probe(other, "/whatever").handled);
	other = falcon_info("1-1");
	other.backend = BACKEND_HIDAPI;
	CHECK_FALSE(probe(other, "/whatever").handled);

	const DeviceAvailability availability = probe(falcon_info("1-1"), "/nonexistent/novint.bin");
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	CHECK(availability.reason.find("not present") != std::string::npos);
	CHECK(std::strlen(FALCON_NO_PERMISSION_REASON) > 0);
	CHECK(std::string(FALCON_NO_PERMISSION_REASON) ==
			"no permission for the Falcon's USB node: install the udev rule (tools/udev, see README Devices)");
}

TEST_CASE("falcon backend: open_device refuses other devices and reports a missing Falcon") {
	std::unique_ptr<HapticDevice> device;
	DeviceInfo other = falcon_info("1-1");
	other.vendor_id = 0x054C;
	Status status = open_device(other, "", device);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "is not a Novint Falcon") != nullptr);
	status = open_device(falcon_info("1-1"), "/nonexistent/novint.bin", device);
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(status.message(), "not present") != nullptr);
	CHECK(device == nullptr);
}
