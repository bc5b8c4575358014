// hidapi's Windows backend as the HID PID backend uses it (hidraw_sysfs_windows.cpp): with no
// sysfs, the descriptor comes from opening the device, so a device that is not there must be
// a clear error, never a crash, an empty success or a claim that it can be opened.
#include <doctest/doctest.h>

#include "devices/device_info.h"
#include "devices/hid/hidraw_sysfs.h"
#include "devices/pid/pid_backend.h"
#include "devices/pid/pid_usages.h"

#include <string>
#include <vector>

using namespace haptics;

namespace {
// The shape of a HID interface name on Windows, for a device that is not plugged in.
constexpr const char *ABSENT_PATH =
		"\\\\?\\hid#vid_1234&pid_5678#0&00000000&0&0000#{4d1e55b2-f16f-11cf-88cb-001111000030}";
} // namespace

TEST_CASE("hid (Windows): the descriptor of an absent device is an error naming it, bytes left empty") {
	std::vector<uint8_t> bytes{ 1, 2, 3 };
	const Status status = hid::read_hidraw_report_descriptor(ABSENT_PATH, bytes);
	CHECK_FALSE(status.ok());
	CHECK(bytes.empty());
	CHECK(std::string(status.message()).find("vid_1234") != std::string::npos);
}

TEST_CASE("hid (Windows): a PID-page device that is absent is handled, not openable, with a reason") {
	DeviceInfo info;
	info.backend = std::string(BACKEND_HIDAPI);
	info.path = ABSENT_PATH;
	info.usage_page = pid::USAGE_PAGE_PID;
	const DeviceAvailability availability = pid::probe(info);
	CHECK(availability.handled);
	CHECK_FALSE(availability.openable);
	CHECK_FALSE(availability.reason.empty());
	// A joystick-page device whose descriptor cannot be read is not claimed by this backend.
	info.usage_page = 0x01;
	CHECK_FALSE(pid::probe(info).handled);
}
