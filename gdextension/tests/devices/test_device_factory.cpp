// The factory's routing: which backend's row claims an enumerated device, what the list
// says about it, and the OpenHaptics entry that exists only through the runtime.

#include "dev_tools/scripted_backends.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "devices/pid/pid_usages.h"
#include "scoped_variable.h"
#include "system/device_factory.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

using namespace haptics;

namespace {

DeviceInfo hidapi_device(uint16_t p_vendor, uint16_t p_product, uint16_t p_usage_page) {
	DeviceInfo info;
	info.id = "hid:/dev/hidraw-test-missing";
	info.backend = std::string(BACKEND_HIDAPI);
	info.path = "/dev/hidraw-test-missing";
	info.vendor_id = p_vendor;
	info.product_id = p_product;
	info.usage_page = p_usage_page;
	return info;
}

const DeviceInfo *find(const DeviceList &p_list, std::string_view p_id) {
	for (const DeviceInfo &info : p_list.devices) {
		if (info.id == p_id) {
			return &info;
		}
	}
	return nullptr;
}

using testing::ScopedVariable;

} // namespace

TEST_CASE("device factory: a PID-page HID device goes to hid-pid, a DualSense to its own driver") {
	std::vector<DeviceInfo> devices = {
		hidapi_device(0x1234, 0x5678, pid::USAGE_PAGE_PID),
		hidapi_device(0x054c, 0x0ce6, 0x01),
		hidapi_device(0x1234, 0x0001, 0x01), // A joystick without force feedback.
	};
	probe_devices(devices);
	CHECK(devices[0].driver == DRIVER_HID_PID);
	CHECK_FALSE(devices[0].openable); // The node is not there.
	CHECK_FALSE(devices[0].unavailable_reason.empty());
	CHECK(devices[1].driver == DRIVER_DUALSENSE);
	CHECK(devices[2].driver.empty());
	CHECK(devices[0].known_haptic);
	CHECK_FALSE(devices[2].known_haptic);
	CHECK(devices[2].unavailable_reason == "no force-feedback driver for this device");

	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(devices[2], {}, device);
	CHECK(opened.code() == StatusCode::UNSUPPORTED);
	CHECK(device == nullptr);
}

TEST_CASE("device factory: the OpenHaptics entry appears when the runtime loads or the player names one") {
	{
		ScopedVariable runtime(openhaptics::HD_LIBRARY_ENV, "/nonexistent/libHD.so");
		const DeviceList list = list_all_devices();
		const DeviceInfo *entry = find(list, openhaptics::OPENHAPTICS_DEFAULT_DEVICE_ID);
		REQUIRE(entry != nullptr);
		CHECK(entry->driver == DRIVER_OPENHAPTICS);
		CHECK_FALSE(entry->openable);
		CHECK(entry->unavailable_reason.find("/nonexistent/libHD.so") != std::string::npos);
		std::unique_ptr<HapticDevice> device;
		CHECK_FALSE(open_listed_device(*entry, {}, device));
		CHECK(device == nullptr);
	}
	{
		ScopedVariable runtime(openhaptics::HD_LIBRARY_ENV, HAPTICS_FAKE_HD_PATH);
		const DeviceList list = list_all_devices();
		const DeviceInfo *entry = find(list, openhaptics::OPENHAPTICS_DEFAULT_DEVICE_ID);
		REQUIRE(entry != nullptr);
		CHECK(entry->openable);
		CHECK(entry->path == HAPTICS_FAKE_HD_PATH);
		std::unique_ptr<HapticDevice> device;
		REQUIRE(open_listed_device(*entry, {}, device));
		REQUIRE(device != nullptr);
		CHECK(device->is_open());
		CHECK(device->capabilities().input_dof == 6);
		CHECK(device->capabilities().output_dof == 3);
		device->close();
	}
	if (!openhaptics::runtime_location().loadable) { // No OpenHaptics on this machine.
		ScopedVariable runtime(openhaptics::HD_LIBRARY_ENV, nullptr);
		CHECK(find(list_all_devices(), openhaptics::OPENHAPTICS_DEFAULT_DEVICE_ID) == nullptr);
	}
}

TEST_CASE("device factory: scripted devices for every threaded driver, listed only when enabled") {
	register_scripted_devices(); // As a development build of the extension does at load.
	{
		ScopedVariable enabled(SCRIPTED_DEVICES_VARIABLE, "1");
		const DeviceList list = list_all_devices();
		std::vector<std::string_view> drivers = { DRIVER_FALCON, DRIVER_DUALSENSE, DRIVER_HID_PID };
		if (HAPTICS_EVDEV) { // The evdev backend is Linux's (cmake/platform.cmake).
			drivers.push_back(DRIVER_EVDEV);
		}
		for (std::string_view driver : drivers) {
			CAPTURE(driver);
			const DeviceInfo *entry = find(list, std::string(SCRIPTED_ID_PREFIX) + std::string(driver));
			REQUIRE(entry != nullptr);
			CHECK(entry->driver == driver);
			CHECK(entry->openable);
		}
		const DeviceInfo *stick = find(list, "scripted:hid-pid");
		REQUIRE(stick != nullptr);
		std::unique_ptr<HapticDevice> device;
		REQUIRE(open_listed_device(*stick, {}, device));
		REQUIRE(device->open());
		CHECK(device->capabilities().input_dof == 2);
		CHECK(device->capabilities().output == ForceOutput::DIRECTIONAL);
		device->close();
	}
	ScopedVariable disabled(SCRIPTED_DEVICES_VARIABLE, nullptr);
	for (const DeviceInfo &info : list_all_devices().devices) {
		CHECK(info.backend != BACKEND_SCRIPTED);
	}
}
