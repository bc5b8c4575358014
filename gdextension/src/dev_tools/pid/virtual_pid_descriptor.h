#pragma once

// Our own PID joystick descriptor, written for this project (not copied from a firmware) to
// exercise the branches AJ's descriptor does not: it is shaped like OpenFFBoard's
// (docs/devices/hid-pid.md, "OpenFFBoard"): Start Delay present, Device Control as a 6-bit Variable bitmask (logical 0..1, so
// the kernel's PERMISSIVE_CONTROL path), one 16-bit direction 0..36000 (centidegrees), a
// constant magnitude of +-32767, a 16-bit duration 0..0xFFFF (all ones = infinite), and
// OFB's feature IDs (Create New Effect 0x11, Block Load 0x12, Pool 0x13). It also uses
// PUSH/POP, a 4-byte extended usage and a usage range, so the parser sees them in context.
//
// Wire layouts (byte 0 = report ID):
//   Input 01 (6 B): buttons 1-8 | X s16 | Y s16 (-32767..32767)
//   Input 02 (3 B): PID State
//   Output 01 Set Effect (16 B): EBI | type 1..11 | duration u16 | trigger repeat u16 |
//          sample period u16 | start delay u16 | gain u8 | trigger button u8 |
//          bit0 X enable, bit1 Y enable, bit2 Direction Enable | direction u16 0..36000
//   Output 05 Set Constant Force (4 B): EBI | magnitude s16 +-32767
//   Output 0A Effect Operation (4 B): EBI | 1 Start, 2 Start Solo, 3 Stop | loop count
//   Output 0B Block Free (2 B): EBI
//   Output 0C Device Control (2 B): bit0 Enable, bit1 Disable, bit2 Stop All, bit3 Reset,
//          bit4 Pause, bit5 Continue
//   Output 0D Device Gain (2 B): 0..255
//   Feature 11 Create New Effect (4 B): type | byte count u16
//   Feature 12 Block Load (5 B): EBI | 1 Success, 2 Full, 3 Error | RAM pool available u16
//   Feature 13 Pool (5 B): RAM pool size u16 | simultaneous max | bit0 managed, bit1 shared

#include <cstdint>
#include <span>
#include <vector>

namespace haptics::pid {

std::span<const uint8_t> virtual_pid_descriptor();

// The same device as a wheel: the stick report carries X only (Input 01, 4 B: buttons | X),
// so PidDevice renders one axis.
std::vector<uint8_t> virtual_pid_wheel_descriptor();

// AJ's composed descriptor (16 buttons) with a 16-bit Start Delay (ms) after Set Effect's
// Sample Period: without one, Linux 6.1's hid-pidff refuses the device ("unknown set_effect
// report layout"); with it, the kernel drives the stick and hidraw is not ours to use.
std::vector<uint8_t> aj_start_delay_descriptor();

} // namespace haptics::pid
