#pragma once

// What Linux sysfs says about a hidraw node, readable without opening the device (so
// without the permissions /dev/hidraw* usually lacks): its report descriptor and whether a
// kernel force-feedback driver (usbhid's hid-pidff) owns it (docs/devices/hid.md).
//
// hidapi 0.13's device path on the hidraw backend is /dev/hidrawN; the HID device behind it
// is /sys/class/hidraw/hidrawN/device. p_sysfs_root exists for tests (a fake tree).
//
// hidraw_sysfs_linux.cpp reads sysfs; hidraw_sysfs_windows.cpp answers the same questions for
// hidapi's Windows backend, whose paths are device interface names (\\?\hid#vid_...): no
// index and no kernel force-feedback driver; the report descriptor is read by opening the
// device (Windows keeps only the parsed form, from which hidapi 0.14 rebuilds the bytes).

#include "core/base/status.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace haptics::hid {

// N of "/dev/hidrawN"; -1 when p_path is not such a path.
int32_t hidraw_index(std::string_view p_path);

// realpath of <root>/class/hidraw/hidrawN/device; "" when it does not resolve.
std::string hidraw_hid_device_sysfs_dir(const std::string &p_hidraw_path, const std::string &p_sysfs_root = "/sys");

// <root>/class/hidraw/hidrawN/device/report_descriptor (binary, <= 4096 bytes).
Status read_hidraw_report_descriptor(const std::string &p_hidraw_path, std::vector<uint8_t> &r_bytes,
		const std::string &p_sysfs_root = "/sys");

// Whether p_path is a hidraw character device (its /sys/dev/char/MAJ:MIN/subsystem is
// hidraw). hidapi 0.13.1's hid_open_path frees its device and then writes an error into it
// when the node is not hidraw (a use-after-free we hit with /dev/null), so the transport
// checks this first. r_reason says why not.
bool is_hidraw_node(const std::string &p_path, std::string *r_reason = nullptr, const std::string &p_sysfs_root = "/sys");

// Some input device under the HID device advertises force feedback: a non-zero word in
// <hid device>/input/input*/capabilities/ff. Then the kernel drives the effects, and raw PID
// reports through hidraw would fight its bookkeeping: use the evdev path instead.
bool kernel_ff_bound(const std::string &p_hidraw_path, const std::string &p_sysfs_root = "/sys");

// Resets the USB device behind a hidraw node (USBDEVFS_RESET on /dev/bus/usb/BBB/DDD): the
// one means a program has to clear a halted (STALLed) endpoint that usbhid owns, since
// clearing the halt alone needs the interface usbhid holds. The device starts over: its
// effects are gone, and the node must be opened again. Needs write access to the USB node
// (the udev rule grants it for the sticks it knows). Windows: UNSUPPORTED.
Status reset_usb_device_of(const std::string &p_hidraw_path, const std::string &p_sysfs_root = "/sys");

// Whether the device node at p_path is still there (a removed device's node goes away).
bool hid_node_exists(const std::string &p_path);

// 0 when this process may open p_path for reading and writing, else the errno that says why
// not (EACCES: the udev rules are missing). Windows has no such check before opening: 0.
int hid_node_access_errno(const std::string &p_path);

} // namespace haptics::hid
