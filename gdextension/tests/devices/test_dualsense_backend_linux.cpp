// The DualSense backend's entry points and the real hidapi transport on this machine: no
// hidraw nodes here, so opening must fail with a clean Status at every level, never crash.

#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_hidapi_transport.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace haptics::dualsense {

namespace {

bool contains(const char *p_text, const char *p_part) {
	return std::strstr(p_text, p_part) != nullptr;
}

} // namespace

TEST_CASE("dualsense backend: probe handles 054C:0CE6 and 0DF2 on hidapi, names the path and the udev rule") {
	DeviceInfo info;
	info.backend = std::string(BACKEND_HIDAPI);
	info.vendor_id = 0x054C;
	info.product_id = 0x0CE6;
	info.path = "/dev/hidraw7";

	DeviceAvailability availability = availability_for(info, 0);
	CHECK(availability.handled);
	CHECK(availability.openable);
	availability = availability_for(info, EACCES);
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	CHECK(availability.reason == "no permission for /dev/hidraw7: install the udev rule (tools/udev, see README Devices)");
	availability = availability_for(info, ENOENT);
	CHECK_FALSE(availability.openable);
	CHECK(contains(availability.reason.c_str(), "/dev/hidraw7"));

	info.product_id = 0x0DF2;
	CHECK(availability_for(info, 0).handled);
	DualSenseModel model = DualSenseModel::DUALSENSE;
	CHECK(is_dualsense(0x054C, 0x0DF2, &model));
	CHECK(model == DualSenseModel::EDGE);
	info.product_id = 0x09CC; // A DualShock 4.
	CHECK_FALSE(availability_for(info, 0).handled);
	info.product_id = 0x0CE6;
	info.vendor_id = 0x054D;
	CHECK_FALSE(availability_for(info, 0).handled);
	info.vendor_id = 0x054C;
	info.backend = std::string(BACKEND_LIBUSB);
	CHECK_FALSE(availability_for(info, 0).handled);
}

TEST_CASE("dualsense hidapi: a nonexistent hidraw path fails with a clean Status, at every level") {
	const char *path = "/dev/hidraw-haptics-test-missing";
	HidapiTransport transport(path);
	Status status = transport.open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(contains(status.message(), path));
	CHECK_FALSE(transport.is_open());
	uint8_t buffer[64];
	size_t size = 7;
	CHECK(transport.read_input(buffer, sizeof(buffer), size) == TransportIo::FAILED);
	CHECK(size == 0);
	CHECK(transport.write_output(buffer, 63) == TransportIo::FAILED);
	CHECK(transport.get_feature(0x20, buffer, sizeof(buffer), size) == TransportIo::FAILED);

	DualSenseDevice device(std::make_unique<HidapiTransport>(path), DualSenseModel::DUALSENSE);
	status = device.open();
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK_FALSE(device.is_open());

	DeviceInfo info;
	info.backend = std::string(BACKEND_HIDAPI);
	info.vendor_id = SONY_VENDOR_ID;
	info.product_id = DUALSENSE_PRODUCT_ID;
	info.path = path;
	const DeviceAvailability availability = probe(info);
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	std::unique_ptr<HapticDevice> opened;
	status = open_device(info, opened);
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(contains(status.message(), path));
	CHECK(opened == nullptr);
	info.product_id = 0x1234;
	CHECK(open_device(info, opened).code() == StatusCode::UNSUPPORTED);

	HidapiTransport empty("");
	CHECK(empty.open().code() == StatusCode::INVALID_ARGUMENT);
}

TEST_CASE("dualsense hidapi: a path that is not a hidraw node is refused before hidapi sees it") {
	// hidapi 0.13.1's hid_open_path crashes on /dev/null; the transport must never hand it one.
	for (const char *path : { "/dev/null", "/dev/zero", "/tmp" }) {
		CAPTURE(path);
		HidapiTransport transport(path);
		const Status status = transport.open();
		CHECK(status.code() == StatusCode::DEVICE_ERROR);
		CHECK(contains(status.message(), "is not a hidraw device node"));
		CHECK_FALSE(transport.is_open());
	}
}

} // namespace haptics::dualsense
