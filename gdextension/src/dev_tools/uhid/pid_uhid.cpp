#include "dev_tools/uhid/pid_uhid.h"

#include <algorithm>
#include <chrono>

namespace haptics::uhid {

void PidHidModel::on_output(std::span<const uint8_t> p_report) {
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	(void)joystick_->write_output(p_report, error);
}

bool PidHidModel::on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) {
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

bool PidHidModel::on_set_report(std::span<const uint8_t> p_report, bool p_feature) {
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	const DeviceIo io = p_feature ? joystick_->send_feature(p_report, error) : joystick_->write_output(p_report, error);
	return io == DeviceIo::OK;
}

size_t PidHidModel::next_input(std::span<uint8_t> r_report) {
	uint8_t buffer[pid::PID_MAX_REPORT_BYTES] = {};
	size_t length = 0;
	char error[pid::ScriptedPidJoystick::ERROR_CAPACITY] = {};
	if (joystick_->read_input(buffer, length, error) != DeviceIo::OK || length > r_report.size()) {
		return 0;
	}
	std::copy_n(buffer, length, r_report.begin());
	return length;
}

PidUhidJoystick::PidUhidJoystick(std::shared_ptr<pid::ScriptedPidJoystick> p_joystick, int p_input_period_ms) :
		model_(std::move(p_joystick)), device_(model_), input_period_ms_(p_input_period_ms) {}

PidUhidJoystick::~PidUhidJoystick() {
	unplug();
}

Status PidUhidJoystick::plug(const UhidIdentity &p_identity) {
	joystick().set_plugged(true);
	const Status created = device_.create(p_identity, joystick().descriptor());
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
	joystick().set_plugged(false);
}

void PidUhidJoystick::pump_inputs() {
	uint8_t report[pid::PID_MAX_REPORT_BYTES] = {};
	while (pumping_) {
		const size_t length = model_.next_input(report);
		if (length > 0) {
			(void)device_.send_input(std::span<const uint8_t>(report, length));
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(input_period_ms_));
	}
}

} // namespace haptics::uhid
