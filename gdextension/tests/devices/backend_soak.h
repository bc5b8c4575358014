#pragma once

// The test every backend passes through the SAME servo loop: HapticsSystem at 1 kHz on its
// own thread for about two seconds against the backend's scripted transport, with a floor
// contact pressing the hand up, frames at 50 Hz from this thread, and an unplug in the
// middle:
//
//   open + start, 1 s rendering -> unplug() -> the servo must stop on its own with
//   DEVICE_DISCONNECTED within a bound -> replug() -> reopen + start, 1 s -> stop.
//
// The backend's own test then checks its transport's record: the bytes per second, that a
// zero force was the last command before the unplug stopped it and at the end, and so on.
// Timing-tolerant: asserts invariants with generous bounds (a loaded 2-core CI machine).

#include "system/haptics_system.h"

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

namespace haptics::test {

struct BackendSoakResult {
	bool opened_first = false;
	bool opened_again = false;
	uint64_t ticks_first = 0; // Servo ticks rendered before the unplug was noticed.
	uint64_t ticks_second = 0; // After the reopen.
	double seconds_first = 0.0;
	double seconds_second = 0.0;
	bool stopped_on_unplug = false; // The servo ended itself after unplug().
	StatusCode status_after_unplug = StatusCode::OK;
	DeviceStatus device_status_after_unplug; // What the HUD would show.
	double peak_total_force_n = 0.0; // Largest |total| the game saw (output snapshots).
	ServoStats stats_second; // The second run's loop and device I/O figures, before stop.
};

struct BackendSoakScript {
	std::function<std::unique_ptr<HapticDevice>()> make_device;
	std::function<void()> unplug;
	std::function<void()> replug;
	double seconds_each = 1.0;
	// The floor's normal (device space); the scripted device should report a position that
	// presses into it (e.g. y < 0) so a force is rendered.
	Vec3 contact_normal{ 0.0, 1.0, 0.0 };
};

inline void soak_frames(HapticsSystem &r_system, const Vec3 &p_normal, double p_seconds) {
	Frame frame;
	add_contact(frame, p_normal);
	const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (std::chrono::steady_clock::now() < end && r_system.is_running()) {
		++frame.sequence;
		r_system.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

inline BackendSoakResult run_backend_soak(HapticsSystem &r_system, const BackendSoakScript &p_script) {
	BackendSoakResult result;
	RenderConfig config = r_system.config();
	config.servo.safety.startup_ramp_s = 0.05;
	config.servo.safety.start_force_n = 0.0; // The script presses at once; do not wait.
	r_system.configure(config);

	result.opened_first = r_system.open_device(p_script.make_device()).ok() && r_system.start(1000.0).ok();
	if (!result.opened_first) {
		return result;
	}
	const auto t0 = std::chrono::steady_clock::now();
	soak_frames(r_system, p_script.contact_normal, p_script.seconds_each);
	result.peak_total_force_n = length(r_system.forces().total);
	p_script.unplug();
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
	while (r_system.is_running() && std::chrono::steady_clock::now() < deadline) {
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
	}
	result.seconds_first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	result.stopped_on_unplug = !r_system.is_running();
	result.ticks_first = r_system.stats().ticks;
	result.status_after_unplug = r_system.servo_status().code();
	result.device_status_after_unplug = r_system.device_status();
	r_system.stop();

	p_script.replug();
	result.opened_again = r_system.open_device(p_script.make_device()).ok() && r_system.start(1000.0).ok();
	if (!result.opened_again) {
		return result;
	}
	const auto t1 = std::chrono::steady_clock::now();
	soak_frames(r_system, p_script.contact_normal, p_script.seconds_each);
	const double peak = length(r_system.forces().total);
	result.peak_total_force_n = peak > result.peak_total_force_n ? peak : result.peak_total_force_n;
	result.stats_second = r_system.stats();
	r_system.stop();
	result.seconds_second = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
	result.ticks_second = r_system.stats().ticks;
	r_system.close_device();
	return result;
}

} // namespace haptics::test
