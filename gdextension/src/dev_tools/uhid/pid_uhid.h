#pragma once

// The scripted PID joystick (dev_tools/pid) as a real HID device of the kernel's, through
// uhid: the joystick's firmware model answers what the kernel passes on from hidraw (Output
// reports, Feature GET and SET), and its stick reports go up as Input reports at the
// joystick's report rate. What the model received is what reached the "wire".

#include "dev_tools/pid/scripted_pid_joystick.h"
#include "dev_tools/uhid/uhid_device.h"

#include <atomic>
#include <memory>
#include <thread>

namespace haptics::uhid {

class PidUhidJoystick final : public UhidHandler {
public:
	// Input reports every p_input_period_ms (AJ firmware: 1 ms; 0: none).
	explicit PidUhidJoystick(std::shared_ptr<pid::ScriptedPidJoystick> p_joystick, int p_input_period_ms = 4);
	~PidUhidJoystick() override; // unplug()

	// Plugs the joystick in: creates the kernel's device with its descriptor and identity.
	Status plug(const UhidIdentity &p_identity);
	// Removes it from the kernel (as pulling the cable does). Idempotent.
	void unplug();
	bool plugged() const { return device_.exists(); }
	const UhidDevice &device() const { return device_; }
	pid::ScriptedPidJoystick &joystick() { return *joystick_; }

	void on_output(std::span<const uint8_t> p_report) override;
	bool on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) override;
	bool on_set_report(std::span<const uint8_t> p_report, bool p_feature) override;

private:
	void pump_inputs();

	std::shared_ptr<pid::ScriptedPidJoystick> joystick_;
	UhidDevice device_;
	int input_period_ms_;
	std::atomic<bool> pumping_{ false };
	std::thread pump_;
};

} // namespace haptics::uhid
