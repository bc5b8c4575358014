#pragma once

// The scripted PID joystick (dev_tools/pid) as a real HID device of the kernel's. PidHidModel
// is the joystick's firmware model behind any HID transport: it answers what the kernel
// passes on (Output reports, Feature GET and SET) and makes the stick's Input reports; what
// it received is what reached the "wire". PidUhidJoystick puts it on uhid (hidraw only: 6.1
// starts no hid-pidff there); a USB gadget (dev_tools/gadget) puts it behind usbhid.

#include "dev_tools/gadget/hid_gadget.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "dev_tools/uhid/uhid_device.h"

#include <atomic>
#include <memory>
#include <thread>

namespace haptics::uhid {

class PidHidModel final : public UhidHandler, public gadget::HidInputSource {
public:
	explicit PidHidModel(std::shared_ptr<pid::ScriptedPidJoystick> p_joystick) :
			joystick_(std::move(p_joystick)) {}

	pid::ScriptedPidJoystick &joystick() { return *joystick_; }

	void on_output(std::span<const uint8_t> p_report) override;
	bool on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) override;
	bool on_set_report(std::span<const uint8_t> p_report, bool p_feature) override;
	size_t next_input(std::span<uint8_t> r_report) override;

private:
	std::shared_ptr<pid::ScriptedPidJoystick> joystick_;
};

class PidUhidJoystick {
public:
	// Input reports every p_input_period_ms (AJ firmware: 1 ms; 0: none).
	explicit PidUhidJoystick(std::shared_ptr<pid::ScriptedPidJoystick> p_joystick, int p_input_period_ms = 4);
	~PidUhidJoystick(); // unplug()

	// Plugs the joystick in: creates the kernel's device with its descriptor and identity.
	Status plug(const UhidIdentity &p_identity);
	// Removes it from the kernel (as pulling the cable does). Idempotent.
	void unplug();
	bool plugged() const { return device_.exists(); }
	const UhidDevice &device() const { return device_; }
	pid::ScriptedPidJoystick &joystick() { return model_.joystick(); }

private:
	void pump_inputs();

	PidHidModel model_;
	UhidDevice device_;
	int input_period_ms_;
	std::atomic<bool> pumping_{ false };
	std::thread pump_;
};

} // namespace haptics::uhid
