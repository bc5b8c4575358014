#pragma once

// What the VM scenarios share: finding a device the way the game's picker does, driving the
// servo with the game's frames, and reading the kernel's log.

#include "core/base/vec3.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/device_info.h"
#include "ktest.h"
#include "system/haptics_system.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace haptics::vm {

// The entries of list_all_devices() with these ids, backend "" = any.
std::vector<DeviceInfo> listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend = "");
// Waits up to p_seconds for an entry with these ids and backend.
bool find_listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend, DeviceInfo &r_info,
		double p_seconds = 5.0);

// The game's frames at 50 Hz for p_seconds: the player stands on a floor.
void stand_on_floor(HapticsSystem &p_system, double p_seconds);

// Opens p_info through the factory and starts the servo at 1 kHz; false (reported) when
// either fails. r_max_force_n: the device's full scale.
bool open_and_run(Report &r_report, const DeviceInfo &p_info, HapticsSystem &r_system, double &r_max_force_n,
		const std::string &p_when);

// Whether the force on the wire (p_wire, N, device space) is the servo's, within p_tolerance_n;
// reports both.
bool same_force(Report &r_report, const Vec3 &p_servo, const Vec3 &p_wire, double p_tolerance_n, const std::string &p_what);

// Whether the servo stops within p_seconds (it notices a device fault at its next tick, which
// under emulation may come a while after the device's I/O thread raised it).
bool servo_stops(const HapticsSystem &p_system, double p_seconds);

// Waits for the device to say it was unplugged and the servo to stop; reports both.
void expect_unplugged(Report &r_report, HapticsSystem &r_system, const std::string &p_when);

// The PID firmware model's force in device space (y up is HID -Y), newtons.
Vec3 pid_wire_n(const pid::ScriptedPidJoystick &p_joystick, double p_max_force_n);
// The last Output report with p_report_id the model received; empty when none.
std::vector<uint8_t> pid_last_output(const pid::ScriptedPidJoystick &p_joystick, uint8_t p_report_id);
// How many it received.
size_t pid_output_count(const pid::ScriptedPidJoystick &p_joystick, uint8_t p_report_id);

// How many kernel log lines contain p_text (the whole ring buffer).
int kernel_log_count(std::string_view p_text);
// The kernel's release, e.g. "6.1.0-50-amd64"; its major and minor.
std::string kernel_release();
bool kernel_older_than(int p_major, int p_minor);

} // namespace haptics::vm
