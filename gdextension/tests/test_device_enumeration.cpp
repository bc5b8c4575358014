#include "devices/device_enumeration.h"

#include "devices/device_catalog.h"

#include <doctest/doctest.h>
#include <hidapi.h>

#include <set>
#include <string>
#include <vector>

using namespace haptics;

namespace {

// Spelled as bytes so the expectation does not depend on the compiler's source charset.
const std::string UBERHAPTIK_UTF8 = "\xC3\x9C"
									"berhaptik \xE2\x9C\x93";
const std::string REPLACEMENT_UTF8 = "\xEF\xBF\xBD";

std::set<std::string> ids_of(const DeviceList &p_list) {
	std::set<std::string> ids;
	for (const DeviceInfo &info : p_list.devices) {
		ids.insert(info.id);
	}
	return ids;
}

bool has_warning_starting_with(const DeviceList &p_list, std::string_view p_prefix) {
	for (const std::string &warning : p_list.warnings) {
		if (std::string_view(warning).substr(0, p_prefix.size()) == p_prefix) {
			return true;
		}
	}
	return false;
}

size_t count_backend(const DeviceList &p_list, std::string_view p_backend) {
	size_t count = 0;
	for (const DeviceInfo &info : p_list.devices) {
		count += info.backend == p_backend ? 1 : 0;
	}
	return count;
}

} // namespace

TEST_CASE("device enumeration: wide_to_utf8 keeps ASCII as is") {
	CHECK(wide_to_utf8(L"Novint Falcon 0403:cb48") == "Novint Falcon 0403:cb48");
	CHECK(wide_to_utf8(L"").empty());
}

TEST_CASE("device enumeration: wide_to_utf8 encodes non-ASCII as UTF-8") {
	CHECK(wide_to_utf8(L"\u00DCberhaptik \u2713") == UBERHAPTIK_UTF8);
	CHECK(wide_to_utf8(L"\u00E9") == "\xC3\xA9"); // Two bytes.
	CHECK(wide_to_utf8(L"\U0001F3AE") == "\xF0\x9F\x8E\xAE"); // Four bytes: a game controller.
}

TEST_CASE("device enumeration: wide_to_utf8 replaces what is not a code point") {
	const wchar_t lone_surrogate[] = { static_cast<wchar_t>(0xD800), L'x', 0 };
	CHECK(wide_to_utf8(lone_surrogate) == REPLACEMENT_UTF8 + "x");
	if constexpr (sizeof(wchar_t) == 4) {
		const wchar_t too_big[] = { static_cast<wchar_t>(0x110000), 0 };
		CHECK(wide_to_utf8(too_big) == REPLACEMENT_UTF8);
	}
}

TEST_CASE("device enumeration: utf16_to_utf8 decodes USB string descriptors") {
	CHECK(utf16_to_utf8(u"Falcon") == "Falcon");
	CHECK(utf16_to_utf8(u"\u00DCberhaptik \u2713") == UBERHAPTIK_UTF8);
	CHECK(utf16_to_utf8(u"\U0001F3AE") == "\xF0\x9F\x8E\xAE"); // A surrogate pair.
	const char16_t swapped_pair[] = { 0xDF8E, 0xD83C, u'!', 0 };
	CHECK(utf16_to_utf8(swapped_pair) == REPLACEMENT_UTF8 + REPLACEMENT_UTF8 + "!");
	const char16_t trailing_high[] = { u'a', 0xD83C, 0 };
	CHECK(utf16_to_utf8(trailing_high) == "a" + REPLACEMENT_UTF8);
}

TEST_CASE("device enumeration: hid entries are merged per path and classified") {
	// hidraw lists one entry per top-level collection: a wheel's joystick collection
	// first, then its force-feedback one, plus a keyboard with no strings at all.
	wchar_t product[] = L"\u00DCberhaptik \u2713";
	wchar_t manufacturer[] = L"ACME";
	wchar_t serial[] = L"42";
	char wheel_path[] = "/dev/hidraw3";
	char keyboard_path[] = "/dev/hidraw0";
	hid_device_info keyboard{};
	keyboard.path = keyboard_path;
	keyboard.vendor_id = 0x046d;
	keyboard.product_id = 0xc31c;
	keyboard.usage_page = 0x01;
	keyboard.usage = 0x06;
	hid_device_info wheel_pid = keyboard;
	wheel_pid.path = wheel_path;
	wheel_pid.vendor_id = 0x1234;
	wheel_pid.product_id = 0x5678;
	wheel_pid.usage_page = HID_USAGE_PAGE_PID;
	wheel_pid.usage = 0x21;
	wheel_pid.product_string = product;
	wheel_pid.manufacturer_string = manufacturer;
	wheel_pid.serial_number = serial;
	wheel_pid.next = &keyboard;
	hid_device_info wheel_joystick = wheel_pid;
	wheel_joystick.usage_page = 0x01;
	wheel_joystick.usage = 0x04;
	wheel_joystick.next = &wheel_pid;

	const std::vector<DeviceInfo> devices = devices_from_hid_list(&wheel_joystick);
	REQUIRE(devices.size() == 2);
	const DeviceInfo &wheel = devices[0];
	CHECK(wheel.id == "hid:/dev/hidraw3");
	CHECK(wheel.backend == BACKEND_HIDAPI);
	CHECK(wheel.path == "/dev/hidraw3");
	CHECK(wheel.vendor_id == 0x1234);
	CHECK(wheel.product_id == 0x5678);
	CHECK(wheel.usage_page == HID_USAGE_PAGE_PID);
	CHECK(wheel.usage == 0x21);
	CHECK(wheel.known_haptic);
	CHECK(wheel.model == "HID PID force-feedback device");
	CHECK(wheel.product == UBERHAPTIK_UTF8);
	CHECK(wheel.manufacturer == "ACME");
	CHECK(wheel.serial == "42");
	const DeviceInfo &keyboard_info = devices[1];
	CHECK(keyboard_info.id == "hid:/dev/hidraw0");
	CHECK_FALSE(keyboard_info.known_haptic);
	CHECK(keyboard_info.product.empty());
	CHECK(devices_from_hid_list(nullptr).empty());
}

TEST_CASE("device enumeration: make_ids_unique suffixes repeats only") {
	std::vector<DeviceInfo> devices(4);
	devices[0].id = "hid:x";
	devices[1].id = "hid:x#2"; // Already taken by a backend: the suffix must skip it.
	devices[2].id = "hid:x";
	devices[3].id = "usb:1-2";
	make_ids_unique(devices);
	CHECK(devices[0].id == "hid:x");
	CHECK(devices[1].id == "hid:x#2");
	CHECK(devices[2].id == "hid:x#3");
	CHECK(devices[3].id == "usb:1-2");
}

TEST_CASE("device enumeration: list_devices puts the simulated device first") {
	const DeviceList list = list_devices();
	REQUIRE_FALSE(list.devices.empty());
	const DeviceInfo &simulated = list.devices.front();
	CHECK(simulated.id == "simulated");
	CHECK(simulated.backend == "simulated");
	CHECK(simulated.known_haptic);
	CHECK(simulated.model == "Simulated 3-DOF device (Omni-like)");
	CHECK(count_backend(list, BACKEND_SIMULATED) == 1);
	CHECK(ids_of(list).size() == list.devices.size());
	for (const DeviceInfo &info : list.devices) {
		CAPTURE(info.id);
		CHECK((info.backend == BACKEND_SIMULATED || info.backend == BACKEND_HIDAPI ||
				info.backend == BACKEND_LIBUSB));
		CHECK(info.known_haptic == !info.model.empty());
	}
	for (const std::string &warning : list.warnings) {
		MESSAGE("warning: " << warning);
		CHECK_FALSE(warning.empty());
	}
}

TEST_CASE("device enumeration: an empty backend explains itself in a warning") {
	// Whatever this machine has, a backend that contributes nothing must say why, or
	// the player cannot tell "no device" from "no permission" or "no bus".
	const DeviceList list = list_devices();
	if (count_backend(list, BACKEND_HIDAPI) == 0) {
		CHECK(has_warning_starting_with(list, "hidapi: "));
	}
	if (count_backend(list, BACKEND_LIBUSB) == 0) {
		CHECK(has_warning_starting_with(list, "libusb: "));
	}
}

TEST_CASE("device enumeration: 100 calls give the same ids and release everything") {
	// Leaks show up under valgrind or the ASan build; here we check stability.
	const std::set<std::string> first = ids_of(list_devices());
	for (int i = 0; i < 100; ++i) {
		const DeviceList list = list_devices();
		REQUIRE(list.devices.front().id == "simulated");
		REQUIRE(ids_of(list) == first);
	}
}
