#pragma once

// What the game can learn about a device before opening it. Plain data, no engine types,
// so the enumeration code and its tests stay free of Godot.

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

// Driver names (DeviceInfo::driver): which code renders a device.
inline constexpr std::string_view DRIVER_SIMULATED = "simulated";
inline constexpr std::string_view DRIVER_HID_PID = "hid-pid";
inline constexpr std::string_view DRIVER_EVDEV = "evdev";
inline constexpr std::string_view DRIVER_FALCON = "falcon";
inline constexpr std::string_view DRIVER_OPENHAPTICS = "openhaptics";
inline constexpr std::string_view DRIVER_DUALSENSE = "dualsense";

inline constexpr std::string_view SIMULATED_DEVICE_ID = "simulated";
inline constexpr std::string_view SIMULATED_DEVICE_MODEL = "Simulated 3-DOF device (Omni-like)";

struct DeviceInfo {
	// Stable across calls while the device stays plugged in the same place, and unique
	// within one enumeration: "simulated", "hid:<path>" or "usb:<bus>-<port path>".
	std::string id;
	std::string backend; // One of the BACKEND_* names.
	uint16_t vendor_id = 0;
	uint16_t product_id = 0;
	std::string path; // Backend-specific; what the backend needs to open the device.
	// UTF-8. Empty when the device could not be opened to read them (often permissions).
	std::string product;
	std::string manufacturer;
	std::string serial;
	// HID only: the top-level collection we chose to report (0 when unknown).
	uint16_t usage_page = 0;
	uint16_t usage = 0;
	bool known_haptic = false;
	std::string model; // Catalog name, e.g. "Novint Falcon"; empty when not in the catalog.
	// Which driver would render it ("hid-pid", "evdev", "falcon", "openhaptics",
	// "dualsense", "simulated"); empty when none does.
	std::string driver;
	// Whether open_device() can open it now; if not, why, in one sentence the player can act
	// on (permissions and the udev rule, a kernel driver bound, the runtime library or the
	// firmware file missing).
	bool openable = false;
	std::string unavailable_reason;
};

// A backend's verdict on one enumerated device (each backend's probe()).
struct DeviceAvailability {
	bool handled = false; // This backend drives the device.
	bool openable = false;
	std::string reason; // Why not, when !openable.
};

} // namespace haptics
