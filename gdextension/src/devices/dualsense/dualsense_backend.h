#pragma once

// Entry points of the DualSense backend (docs/devices/dualsense.md): which enumerated devices
// it drives, and
// opening one over hidapi. The same device over a software model of the pad is a development
// tool (dev_tools/dualsense/scripted_dualsense_device.h).
//
//   probe(info)        handled: backend "hidapi", VID 054C, PID 0CE6 (DualSense) or 0DF2
//                      (Edge). Openable unless the hidraw node is missing or we may not read
//                      and write it (then the reason names the path and the udev rule).
//   open_device(info)  probe, then a DualSenseDevice over a HidapiTransport on info.path,
//                      opened. The caller hands it to HapticsSystem::open_device, whose
//                      open() re-opens it cleanly (open() is idempotent: close, then open).
//
// Coexistence: with the kernel's hid-playstation bound (Linux >= 5.12) the kernel also
// writes output reports through the same pad (LEDs at start-up, its own sequence on BT). Ours
// go through hidraw beside it; the pad applies whichever came last, field by field.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/dualsense/dualsense_device.h"

#include <cstdint>
#include <memory>

namespace haptics::dualsense {

inline constexpr uint16_t SONY_VENDOR_ID = 0x054C;
inline constexpr uint16_t DUALSENSE_PRODUCT_ID = 0x0CE6;
inline constexpr uint16_t DUALSENSE_EDGE_PRODUCT_ID = 0x0DF2;

// True for the two pads; r_model (optional) says which.
bool is_dualsense(uint16_t p_vendor_id, uint16_t p_product_id, DualSenseModel *r_model = nullptr);

// The verdict given the result of access(path, R_OK | W_OK): 0, or the errno it failed with.
// Pure, for tests (this machine runs the tests as root, where access() always succeeds).
DeviceAvailability availability_for(const DeviceInfo &p_info, int p_access_errno);

DeviceAvailability probe(const DeviceInfo &p_info);

// UNSUPPORTED when probe() does not handle the device; the probe's reason (DEVICE_ERROR, or
// NO_DEVICE when the node is gone) when it is not openable; else the open device or open()'s
// Status. r_device is only set on success.
Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device, const DualSenseConfig &p_config = {});

} // namespace haptics::dualsense
