#pragma once

// What the game can learn about a device before opening it. Plain data, no engine types,
// so the enumeration code and its tests stay free of Godot.

#include "devices/device_info.gen.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace haptics {

inline constexpr std::string_view BACKEND_SIMULATED = "simulated";
inline constexpr std::string_view BACKEND_HIDAPI = "hidapi";
inline constexpr std::string_view BACKEND_LIBUSB = "libusb";
inline constexpr std::string_view BACKEND_EVDEV = "evdev"; // Linux input event nodes.
// The user's OpenHaptics runtime (devices by configuration name, not by bus).
inline constexpr std::string_view BACKEND_OPENHAPTICS = "openhaptics";
// SDL 3's haptics (devices/sdl, where built: HAPTICS_SDL3).
inline constexpr std::string_view BACKEND_SDL = "sdl";

// Driver names (DeviceInfo::driver): which code renders a device.
inline constexpr std::string_view DRIVER_SIMULATED = "simulated";
inline constexpr std::string_view DRIVER_HID_PID = "hid-pid";
inline constexpr std::string_view DRIVER_EVDEV = "evdev";
inline constexpr std::string_view DRIVER_FALCON = "falcon";
inline constexpr std::string_view DRIVER_OPENHAPTICS = "openhaptics";
inline constexpr std::string_view DRIVER_DUALSENSE = "dualsense";
inline constexpr std::string_view DRIVER_SDL = "sdl";

inline constexpr std::string_view SIMULATED_DEVICE_ID = "simulated";
inline constexpr std::string_view SIMULATED_DEVICE_MODEL = "Simulated 3-DOF device (Omni-like)";

// DeviceInfo and DeviceList: device_info.schema.toml.

// A backend's verdict on one enumerated device (each backend's probe()).
struct DeviceAvailability {
	bool handled = false; // This backend drives the device.
	bool openable = false;
	std::string reason; // Why not, when !openable.
};

} // namespace haptics
