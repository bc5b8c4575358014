#pragma once

// The report descriptor of ArduinoJoystickWithFFBLibrary ("AJ", docs/devices/hid-pid.md), the open
// firmware most DIY force-feedback joysticks and wheels run: the PID part verbatim (1227
// bytes, SHA-256 d4b07685…f36e9) and the Generic Desktop joystick part its Joystick.cpp
// builds in front of it at run time [AJ @ ed86e27 src/Joystick.cpp, FFBDescriptor.h].
//
// What AJ's Joystick.cpp really sends (read at the commit docs/devices/sources.md names):
// Application (Joystick),
// Usage Pointer, Report ID 1, a Physical collection, the buttons, then a second Physical
// collection around X/Y, and ONE End Collection, which closes the outer Physical collection,
// not the Application. The PID part's extra trailing End Collection (quirk 2) then closes
// the Application, so the composed descriptor AJ devices send is balanced and every PID
// collection sits inside the Joystick application. (A first reading had the joystick part
// closed before the PID part; that holds for the variant compose_aj_descriptor(..., true),
// kept to test the unbalanced case a tolerant parser must accept.)

#include <cstdint>
#include <span>
#include <vector>

namespace haptics::pid {

inline constexpr size_t AJ_PID_DESCRIPTOR_SIZE = 1227;
std::span<const uint8_t> aj_pid_descriptor();

inline constexpr uint8_t AJ_JOYSTICK_REPORT_ID = 0x01;
inline constexpr int32_t AJ_AXIS_MIN = -32767; // `16 01 80`
inline constexpr int32_t AJ_AXIS_MAX = 32767; // `26 FF 7F`

// The joystick part for p_button_count buttons (1..32, padded to whole bytes) and X, Y,
// followed by the PID part. p_close_application adds the End Collection that first reading assumed,
// which leaves the PID part's trailing one unmatched.
std::vector<uint8_t> compose_aj_descriptor(uint8_t p_button_count, bool p_close_application = false);

} // namespace haptics::pid
