#include "dev_tools/uhid/pid_uhid.h"

#include <chrono>

namespace haptics::uhid {

PidUhidJoystick::PidUhidJoystick(std::shared_ptr<pid::ScriptedPidJoystick> p_joystick, int p_input_period_ms) :
		joystick_(std::move(p_joystick)), device_(*this), input_period_ms_(p_input_period_ms) {}

PidUhidJoystick::~PidUhidJoystick() {
	unplug();
}

Status PidUhidJoystick::plug(const UhidIdentity &p_identity) {
	joystick_->set_plugged(true);
	const Status created = device_.create(p_identity, joystick_->descriptor());
	if (created && input_period_ms_ > 0) {
		pumping_ = true;
		pump_ = std::thread(&PidUhidJoystick::pump_inputs, this);
	}
	return created;
}

void PidUhidJoystick::unplug() {
	pumping_ = false;
	if (pump_.joinable()) {
		pump_.join();
	}
	device_.destroy();
	// The firmware model restarts from power-on when plugged back, as the hardware does.
	joystick_->set_plugged(false);
}

void PidUhidJoystick::on_output(std::span<const uint8_t> p_report) {
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	(void)joystick_->write_output(p_report, error);
}

bool PidUhidJoystick::on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) {
	if (!p_feature) {
		return false;
	}
	uint8_t buffer[pid::PID_MAX_REPORT_BYTES] = { p_id };
	size_t length = 0;
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	if (joystick_->get_feature(buffer, length, error) != DeviceIo::OK || length == 0) {
		return false;
	}
	r_reply.assign(buffer, buffer + length);
	return true;
}

bool PidUhidJoystick::on_set_report(std::span<const uint8_t> p_report, bool p_feature) {
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	const DeviceIo io = p_feature ? joystick_->send_feature(p_report, error) : joystick_->write_output(p_report, error);
	return io == DeviceIo::OK;
}

void PidUhidJoystick::pump_inputs() {
	uint8_t buffer[pid::PID_MAX_REPORT_BYTES] = {};
	while (pumping_) {
		size_t length = 0;
		char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
		if (joystick_->read_input(buffer, length, error) == DeviceIo::OK && length > 0) {
			(void)device_.send_input(std::span<const uint8_t>(buffer, length));
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(input_period_ms_));
	}
}

} // namespace haptics::uhid
