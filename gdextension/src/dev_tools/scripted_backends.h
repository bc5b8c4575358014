#pragma once

// Development builds list, besides the hardware present, one device per backend that runs
// the backend's real protocol over a software model of its hardware ("scripted:<driver>",
// scripted_device.h): for the headless tests and for trying a backend's code path without
// its hardware. They are listed only when the environment variable
// HAPTICS_SCRIPTED_DEVICES=1. Their stick or stylus follows the simulated hand target, and
// their cable (HapticDevice::software_cable) stays unplugged across reopen attempts.
//
// register_scripted_devices() adds them to the device factory (system/device_factory.h);
// the library calls it at initialisation when built with HAPTICS_DEV_TOOLS, the doctests
// before they list devices. Idempotent.

#include <string_view>

namespace haptics {

inline constexpr std::string_view BACKEND_SCRIPTED = "scripted";
inline constexpr std::string_view SCRIPTED_ID_PREFIX = "scripted:";
inline constexpr const char *SCRIPTED_DEVICES_VARIABLE = "HAPTICS_SCRIPTED_DEVICES";

void register_scripted_devices();
bool scripted_devices_enabled();

} // namespace haptics
