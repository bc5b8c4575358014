#pragma once

// Lists every device the game could offer: the built-in simulated device, then what hidapi
// and libusb see. Missing buses and unopenable devices are normal (containers, no udev
// rules), so they become warnings for the player rather than errors.

#include "devices/device_info.h"

#include <string>
#include <string_view>
#include <vector>

struct hid_device_info;

namespace haptics {

// DeviceList (device_info.schema.toml): the simulated device always first, so there is always
// something to play with; warnings for people ("libusb: no USB bus available
// (LIBUSB_ERROR_OTHER)").

// Never throws and never prints. Safe to call from several threads. It takes a few
// milliseconds per bus but may block for seconds on a misbehaving USB device (libusb
// waits 1 s per unanswered string request): call it from a menu, never from the servo
// loop. It calls hid_exit() before returning, so do not call it while another part of the
// program keeps hidapi devices open.
DeviceList list_devices() noexcept;

DeviceInfo make_simulated_device_info();

// hidapi reports one entry per top-level collection; this merges them into one device per
// path, keeping the force-feedback collection when there is one. Exposed for tests.
std::vector<DeviceInfo> devices_from_hid_list(const hid_device_info *p_list);

// Appends "#2", "#3"... to repeated ids so that ids stay unique whatever a backend reports.
void make_ids_unique(std::vector<DeviceInfo> &r_devices);

// hidapi strings are wchar_t (UTF-32 on Linux, UTF-16 on Windows) and USB string
// descriptors are UTF-16LE. Invalid code units become U+FFFD instead of failing.
std::string wide_to_utf8(std::wstring_view p_text);
std::string utf16_to_utf8(std::u16string_view p_text);

} // namespace haptics
