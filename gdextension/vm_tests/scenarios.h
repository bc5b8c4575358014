#pragma once

// The scenarios the VM's test program runs, one per device path; each returns its failures.

#include "ktest.h"

#include <string>

namespace haptics {
class HapticsSystem;
struct DeviceInfo;
} // namespace haptics
namespace haptics::gadget {
class HidGadget;
}
namespace haptics::pid {
class ScriptedPidJoystick;
}
namespace haptics::uhid {
class DualSenseUhidPad;
}
namespace haptics::uinput {
class UinputFfDevice;
}

namespace haptics::vm {

int run_pid_hidraw();
int run_pid_usb();
int run_falcon_usb();
int run_dualsense();
int run_evdev_uinput();
// SDL 3's haptics over the kernel's drivers (sdl.cpp; built with HAPTICS_SDL3).
int run_sdl();
// Godot's own SDL (a second process running libSDL3 as Godot 4.6 does, sdl_godot.h) beside our
// DualSense backend (sdl_beside_dualsense.cpp) and our evdev backend on a wheel
// (sdl_beside_wheel.cpp); built with HAPTICS_SDL3.
int run_godot_sdl_dualsense();
int run_godot_sdl_wheel();

// The DualSense scenario's evdev part (dualsense_evdev.cpp), on the plugged pad.
void run_dualsense_evdev(Report &r_report, uhid::DualSenseUhidPad &p_pad);
// The evdev-uinput scenario's side-by-side checks of the real and the scripted kernel
// (kernel_facts.cpp), on the created stick.
void check_kernel_facts(Report &r_report, uinput::UinputFfDevice &p_stick);
// The PID scenario's outages (pid_outage.cpp): the stick's OUT endpoint NAKs for 1.5 s, then
// STALLs; p_info: the entry opened; p_kernel_owns: hid-pidff drives it (evdev), else our
// backend (hidraw). Leaves the stick's outputs released (a STALL stays until the host clears
// it).
void check_outages(Report &r_report, gadget::HidGadget &r_stick, pid::ScriptedPidJoystick &r_joystick,
		HapticsSystem &r_system, const DeviceInfo &p_info, double p_max_force_n, bool p_kernel_owns,
		const std::string &p_label);

} // namespace haptics::vm
