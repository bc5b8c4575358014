// A PID stick that stops taking output reports (issue 38, item 5), on the USB path the
// probe chose: its interrupt OUT endpoint NAKs for 1.5 s (a busy firmware), then STALLs
// (halted). Through hidraw our own write waits while the endpoint NAKs, and the device
// status must say so at once and clear when the wire moves again; a STALL fails the write,
// and the status says why; our backend then resets the USB device (the only means that
// reaches a halt usbhid owns), and opening it again renders the servo's force. Through the
// kernel's hid-pidff (evdev) the updates go into
// usbhid's queue and the kernel drops what overflows without telling user space: measured
// and reported here, not checked, since no status can see it.

#include "dev_tools/gadget/hid_gadget.h"
#include "rig.h"
#include "scenarios.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

namespace haptics::vm {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point p_start) {
	return std::chrono::duration<double>(Clock::now() - p_start).count();
}

// Drives the game's frames while p_watch polls the status every 2 ms, for p_seconds.
void play_while(HapticsSystem &r_system, double p_seconds, const std::function<void()> &p_watch) {
	std::thread frames([&] { stand_on_floor(r_system, p_seconds); });
	const Clock::time_point start = Clock::now();
	while (since(start) < p_seconds) {
		p_watch();
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	frames.join();
}

void nak(Report &r_report, gadget::HidGadget &r_stick, pid::ScriptedPidJoystick &r_joystick, HapticsSystem &r_system,
		double p_max_force_n, bool p_kernel_owns, const std::string &p_when) {
	const int queue_full_before = kernel_log_count("output queue full");
	r_joystick.set_stick(0.3, 0.6);
	r_stick.hold_outputs(true);
	const Clock::time_point start = Clock::now();
	double seen_s = -1.0;
	double stuck_max_s = 0.0;
	play_while(r_system, 1.5, [&] {
		const DeviceStatus status = r_system.device_status();
		if (status.output_stuck_s > 0.0 && seen_s < 0.0) {
			seen_s = since(start);
		}
		stuck_max_s = std::max(stuck_max_s, status.output_stuck_s);
	});
	r_stick.hold_outputs(false);
	const Clock::time_point released = Clock::now();
	double cleared_s = -1.0;
	play_while(r_system, 1.0, [&] {
		if (cleared_s < 0.0 && r_system.device_status().output_stuck_s == 0.0) {
			cleared_s = since(released);
		}
	});
	char text[220];
	std::snprintf(text, sizeof(text),
			"%s: endpoint NAKing for 1.5 s: status said so after %.3f s (stuck up to %.2f s), cleared %.3f s after; kernel dropped %d (\"output queue full\")",
			p_when.c_str(), seen_s, stuck_max_s, cleared_s, kernel_log_count("output queue full") - queue_full_before);
	r_report.info(text);
	if (p_kernel_owns) {
		r_report.info(p_when + ": through hid-pidff no write waits and no status can see the queue overflow");
	} else {
		// Emulation stretches time: the bound is generous; the note gives the number.
		r_report.check(seen_s >= 0.0 && seen_s < 0.5, p_when + ": the device status says the wire is stuck");
		r_report.check(stuck_max_s > 1.0, p_when + ": and keeps saying so while it is");
		r_report.check(cleared_s >= 0.0, p_when + ": the status clears when the wire moves again");
	}
	stand_on_floor(r_system, 0.5);
	same_force(r_report, r_system.forces().total, pid_wire_n(r_joystick, p_max_force_n), 0.03 * p_max_force_n,
			p_when + ": after the NAK the wire holds the servo's force again");
}

void stall(Report &r_report, gadget::HidGadget &r_stick, pid::ScriptedPidJoystick &r_joystick, HapticsSystem &r_system,
		const DeviceInfo &p_info, bool p_kernel_owns, const std::string &p_when) {
	const int irq_errors_before = kernel_log_count("output irq status -32");
	std::thread frames([&] { stand_on_floor(r_system, 0.5); });
	const Status halted = r_stick.stall_outputs();
	frames.join();
	// The halt answers every report with STALL whether or not a read waits; the reads must
	// wait again for when the host clears it (a reset does).
	r_stick.hold_outputs(false);
	if (!r_report.check(halted.ok(), p_when + ": the gadget halted its OUT endpoint " + halted.message())) {
		return;
	}
	// A held force needs no report, so a halt shows at the next one the player needs: the
	// hand moves now, and the status must follow within the bound from this moment.
	r_joystick.set_stick(-0.2, 0.5);
	const Clock::time_point start = Clock::now();
	double failed_s = -1.0;
	play_while(r_system, 1.5, [&] {
		if (failed_s < 0.0 && r_system.device_status().io != DeviceIo::OK) {
			failed_s = since(start);
		}
	});
	const DeviceStatus status = r_system.device_status();
	char text[384];
	std::snprintf(text, sizeof(text), "%s: endpoint stalled: the hand moved, status %s after %.3f s (\"%s\"); kernel \"output irq status -32\" %d times",
			p_when.c_str(), DEVICE_IO_NAMES[static_cast<int>(status.io)], failed_s, static_cast<const char *>(status.reason),
			kernel_log_count("output irq status -32") - irq_errors_before);
	r_report.info(text);
	if (!p_kernel_owns) {
		// Emulation stretches time: the bound is generous; the note gives the number.
		r_report.check(failed_s >= 0.0 && failed_s < 0.5 && status.reason[0] != '\0',
				p_when + ": once the force changes, the status says the device failed, and why");
		r_report.check(servo_stops(r_system, 2.0), p_when + ": the servo stops (zero force)");
		r_report.check(std::strstr(status.reason, "reset it") != nullptr, p_when + ": the backend reset the device");
		// What the game's reconnect does: list it again, open it, render.
		r_system.close_device();
		DeviceInfo again;
		double max_force_n = 0.0;
		if (r_report.check(find_listed(p_info.vendor_id, p_info.product_id, p_info.backend, again), p_when + ": listed after the reset") &&
				open_and_run(r_report, again, r_system, max_force_n, p_when + ", reopened")) {
			r_joystick.set_stick(0.0, 0.8);
			stand_on_floor(r_system, 1.0);
			same_force(r_report, r_system.forces().total, pid_wire_n(r_joystick, max_force_n), 0.03 * max_force_n,
					p_when + ": after the reset the wire holds the servo's force again");
		}
	}
}

} // namespace

void check_outages(Report &r_report, gadget::HidGadget &r_stick, pid::ScriptedPidJoystick &r_joystick,
		HapticsSystem &r_system, const DeviceInfo &p_info, double p_max_force_n, bool p_kernel_owns,
		const std::string &p_label) {
	nak(r_report, r_stick, r_joystick, r_system, p_max_force_n, p_kernel_owns, p_label + ", NAK");
	stall(r_report, r_stick, r_joystick, r_system, p_info, p_kernel_owns, p_label + ", STALL");
	r_stick.hold_outputs(false);
}

} // namespace haptics::vm
