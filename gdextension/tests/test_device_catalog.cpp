#include "devices/device_catalog.h"

#include <doctest/doctest.h>

using namespace haptics;

TEST_CASE("catalog: Novint Falcon is known on any USB backend") {
	for (const std::string_view backend : { BACKEND_LIBUSB, BACKEND_HIDAPI }) {
		const DeviceClassification result = classify_device(backend, 0x0403, 0xcb48, 0);
		CHECK(result.known_haptic);
		CHECK(result.model == "Novint Falcon");
	}
}

TEST_CASE("catalog: Sony DualSense is known") {
	const DeviceClassification result = classify_device(BACKEND_HIDAPI, 0x054c, 0x0ce6, 0x01);
	CHECK(result.known_haptic);
	CHECK(result.model == "Sony DualSense");
}

TEST_CASE("catalog: any HID device on usage page 0x0F is a PID force-feedback device") {
	const DeviceClassification result = classify_device(BACKEND_HIDAPI, 0x1234, 0x5678, 0x0F);
	CHECK(result.known_haptic);
	CHECK(result.model == "HID PID force-feedback device");
}

TEST_CASE("catalog: a specific row wins over the usage-page rule") {
	const DeviceClassification result = classify_device(BACKEND_HIDAPI, 0x054c, 0x0ce6, 0x0F);
	CHECK(result.model == "Sony DualSense");
}

TEST_CASE("catalog: usage page 0x0F means nothing outside HID") {
	// libusb never knows usage pages; a stray value must not make a device haptic.
	CHECK_FALSE(classify_device(BACKEND_LIBUSB, 0x1234, 0x5678, 0x0F).known_haptic);
}

TEST_CASE("catalog: an ordinary keyboard is not haptic") {
	// Logitech K120: Generic Desktop page, keyboard usage.
	const DeviceClassification result = classify_device(BACKEND_HIDAPI, 0x046d, 0xc31c, 0x01);
	CHECK_FALSE(result.known_haptic);
	CHECK(result.model.empty());
	CHECK_FALSE(classify_device(BACKEND_LIBUSB, 0x046d, 0xc31c, 0).known_haptic);
}

TEST_CASE("catalog: near misses of a VID:PID do not match") {
	CHECK_FALSE(classify_device(BACKEND_LIBUSB, 0x0403, 0x6001, 0).known_haptic); // Plain FTDI.
	CHECK_FALSE(classify_device(BACKEND_LIBUSB, 0x054d, 0x0ce6, 0).known_haptic);
}

TEST_CASE("catalog: the simulated backend is the Omni-like simulated device") {
	const DeviceClassification result = classify_device(BACKEND_SIMULATED, 0, 0, 0);
	CHECK(result.known_haptic);
	CHECK(result.model == SIMULATED_DEVICE_MODEL);
}

TEST_CASE("catalog: apply_catalog fills known_haptic and model, and clears stale ones") {
	DeviceInfo info;
	info.backend = BACKEND_LIBUSB;
	info.vendor_id = 0x0403;
	info.product_id = 0xcb48;
	apply_catalog(info);
	CHECK(info.known_haptic);
	CHECK(info.model == "Novint Falcon");

	info.product_id = 0x6001;
	apply_catalog(info);
	CHECK_FALSE(info.known_haptic);
	CHECK(info.model.empty());
}
