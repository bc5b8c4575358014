#pragma once

// A backend's real device class running over its scripted transport (a software model of
// the hardware), as the game opens it with the id "scripted:<driver>" (scripted_backends.h).
// Everything is forwarded to the backend's device, so the protocol, the I/O thread and the
// fault handling are the real ones; two things are added for tests and demos:
//  - the model's stylus or stick follows the simulated hand target (so a test can push into
//    a wall through, say, a scripted PID joystick's deflection), and
//  - a cable: set_plugged(false) unplugs the model (transfers fail as on hardware) and keeps
//    the device unplugged across reopen attempts until set_plugged(true), like a real cable.

#include "core/device/device.h"

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace haptics {

struct ScriptedModelHooks {
	// Game thread, while the servo may run: where the model's stylus/stick is (metres,
	// device space; a joystick's deflection is this divided by its nominal radius).
	std::function<void(const Vec3 &)> set_position;
	std::function<void(bool)> set_plugged;
};

class ScriptedDevice final : public HapticDevice, public SoftwareCable {
public:
	ScriptedDevice(std::unique_ptr<HapticDevice> p_inner, ScriptedModelHooks p_hooks, std::atomic<bool> &r_cable);
	~ScriptedDevice() override;

	Status open() override;
	void close() override { inner_->close(); }
	bool is_open() const override { return inner_->is_open(); }
	Status calibrate() override { return inner_->calibrate(); }
	DeviceCapabilities capabilities() const override { return inner_->capabilities(); }
	const char *name() const override { return inner_->name(); }
	DeviceStatus status() const override { return inner_->status(); }
	DeviceIoStats io_stats() const override { return inner_->io_stats(); }
	void begin_tick(double p_dt_s) override { inner_->begin_tick(p_dt_s); }
	DeviceIo read_state(DeviceState &r_state) override { return inner_->read_state(r_state); }
	DeviceIo write_force(const ForceCommand &p_command) override { return inner_->write_force(p_command); }

	bool has_hand() const override { return true; }
	Status set_hand_target(const Vec3 &p_target_m) override;

	SoftwareCable *software_cable() override { return this; }
	void set_plugged(bool p_plugged) override;

private:
	std::unique_ptr<HapticDevice> inner_;
	ScriptedModelHooks hooks_;
	std::atomic<bool> &cable_;
};

} // namespace haptics
