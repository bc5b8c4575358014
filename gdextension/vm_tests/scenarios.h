#pragma once

// The scenarios the VM's test program runs, one per device path; each returns its failures.

namespace haptics::vm {

int run_pid_hidraw();
int run_pid_usb();
int run_falcon_usb();

} // namespace haptics::vm
