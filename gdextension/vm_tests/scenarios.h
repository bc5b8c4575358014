#pragma once

// The scenarios the VM's test program runs, one per device path; each returns its failures.

#include "ktest.h"

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

// The DualSense scenario's evdev part (dualsense_evdev.cpp), on the plugged pad.
void run_dualsense_evdev(Report &r_report, uhid::DualSenseUhidPad &p_pad);
// The evdev-uinput scenario's side-by-side checks of the real and the scripted kernel
// (kernel_facts.cpp), on the created stick.
void check_kernel_facts(Report &r_report, uinput::UinputFfDevice &p_stick);

} // namespace haptics::vm
