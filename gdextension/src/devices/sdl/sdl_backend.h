#pragma once

// The SDL backend's entry points for the device factory (system/device_factory.cpp): the
// haptics SDL lists, whether each is ours to open and why not, and opening one.
//
// Which backend drives a device that two can reach (docs/devices/sdl.md, "Which backend wins"):
//  - Linux: every SDL haptic is a kernel event node underneath (SDL's Linux driver opens
//    /dev/input/eventN and issues the same EVIOCSFF our evdev backend does), and SDL_OpenHaptic
//    sets the player's gain to 100 and the centring spring to 0 on its own, which the evdev
//    backend leaves to the game's HapticDeviceOpenOptions. So the evdev backend drives them:
//    SDL's entries are listed, not openable, "driven by the evdev backend here", and SDL is not
//    asked to open them (not even to read their features: that alone would set the gain).
//    HAPTICS_SDL_ON_LINUX=1 hands them to SDL instead (the kernel VM tests do). SDL's joysticks
//    are not listed: every Linux pad with rumble is an event node, so a haptic already.
//  - Windows: SDL drives its DirectInput haptics and rumbles the pads SDL 3 has no haptic for
//    (XInput, and the pads SDL's HIDAPI drivers know) through SDL_RumbleJoystick.
//  - Everywhere, the specialised backends on a bus (raw HID PID, DualSense, Falcon) win a device
//    they can open now: an SDL entry whose USB ids are those of such an entry is listed, not
//    openable, "driven by the <driver> backend here (<its id>)", and SDL does not open it (see
//    sdl_runtime.h). A stick both our hid-pid (hidapi) and SDL's DirectInput reach is hid-pid's:
//    it paces its reports to the endpoint, honours the game's gain and spring, and reads the
//    stick's position; when hid-pid cannot open it (its reports are not usable, another program
//    holds it), SDL's entry is offered instead.
// Each entry: backend and driver "sdl", id "sdl:<key>" and path "<key>" (sdl_runtime.h: SDL's
// name and its rank among the entries of that name), product SDL's name, the USB ids where
// SDL's joystick gives them.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/sdl/sdl_device.h"
#include "devices/sdl/sdl_runtime.h"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace haptics::sdl {

inline constexpr char SDL_ON_LINUX_ENV[] = "HAPTICS_SDL_ON_LINUX";
inline constexpr char SDL_ID_PREFIX[] = "sdl:";

// Whether SDL drives the devices it lists here (see above): on Linux only with
// HAPTICS_SDL_ON_LINUX=1.
bool sdl_drives_here();
// Whether SDL's joysticks are listed here: Windows only (see above).
bool sdl_lists_joysticks_here();

// The claims p_others make (see above): one per openable hidapi or libusb entry of a
// specialised backend, its reason naming the driver and the entry. Two devices with the same
// USB ids are one to this rule: a claim covers both.
std::vector<SdlClaim> sdl_claims(std::span<const DeviceInfo> p_others);

// p_entry as a DeviceInfo, with its verdict: p_drives false -> "driven by the evdev backend".
DeviceInfo sdl_device_info(const SdlHapticEntry &p_entry, bool p_drives);

// Appends SDL's devices after p_others' verdicts (their claims); none, and a warning when SDL
// is wanted but missing. Game thread.
void append_sdl_devices(std::span<const DeviceInfo> p_others, std::vector<DeviceInfo> &r_devices,
		std::vector<std::string> &r_warnings);
void append_sdl_devices(SdlRuntime &r_runtime, const SdlListOptions &p_options, std::vector<DeviceInfo> &r_devices,
		std::vector<std::string> &r_warnings);

// handled when p_info.backend is "sdl": the verdict of the last listing for its key.
DeviceAvailability probe(const DeviceInfo &p_info);
DeviceAvailability probe(SdlRuntime &r_runtime, bool p_drives, const DeviceInfo &p_info);

// Makes the device and opens it; r_device untouched on failure.
Status open_device(const DeviceInfo &p_info, bool p_keep_spring, std::unique_ptr<HapticDevice> &r_device);
Status open_device(SdlRuntime &r_runtime, bool p_drives, const DeviceInfo &p_info, bool p_keep_spring,
		std::unique_ptr<HapticDevice> &r_device);

} // namespace haptics::sdl
