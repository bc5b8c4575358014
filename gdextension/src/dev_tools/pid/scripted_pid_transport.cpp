// The transport side of the scripted PID joystick: what PidDevice holds instead of a hidapi
// handle. Each transport keeps its own open flag and last error; the model is shared.

#include "dev_tools/pid/scripted_pid_joystick.h"

#include <cstdio>

namespace haptics::pid {

namespace {

class ScriptedHidTransport final : public hid::HidTransport {
public:
	explicit ScriptedHidTransport(std::shared_ptr<ScriptedPidJoystick> p_joystick) :
			joystick_(std::move(p_joystick)) {}

	Status open() override {
		if (!joystick_->plugged()) {
			return Status::error(StatusCode::DEVICE_DISCONNECTED, "scripted PID joystick: unplugged");
		}
		open_ = true;
		return Status::success();
	}
	void close() override { open_ = false; }
	bool is_open() const override { return open_; }
	Status report_descriptor(std::vector<uint8_t> &r_bytes) override {
		const std::span<const uint8_t> bytes = joystick_->descriptor();
		r_bytes.assign(bytes.begin(), bytes.end());
		return Status::success();
	}
	DeviceIo write_output(std::span<const uint8_t> p_report) override {
		return open_ ? checked(joystick_->write_output(p_report, error_)) : not_open();
	}
	DeviceIo send_feature(std::span<const uint8_t> p_report) override {
		return open_ ? checked(joystick_->send_feature(p_report, error_)) : not_open();
	}
	DeviceIo get_feature(std::span<uint8_t> p_buffer, size_t &r_length) override {
		r_length = 0;
		return open_ ? checked(joystick_->get_feature(p_buffer, r_length, error_)) : not_open();
	}
	DeviceIo read_input(std::span<uint8_t> p_buffer, size_t &r_length) override {
		r_length = 0;
		return open_ ? checked(joystick_->read_input(p_buffer, r_length, error_)) : not_open();
	}
	const char *last_error() const override { return error_; }

private:
	DeviceIo checked(DeviceIo p_io) {
		if (p_io == DeviceIo::OK) {
			error_[0] = '\0';
		}
		return p_io;
	}
	DeviceIo not_open() {
		std::snprintf(error_, sizeof(error_), "the scripted PID joystick is not open");
		return DeviceIo::FAILED;
	}

	std::shared_ptr<ScriptedPidJoystick> joystick_;
	bool open_ = false;
	char error_[ScriptedPidJoystick::ERROR_CAPACITY] = {};
};

} // namespace

std::unique_ptr<hid::HidTransport> make_scripted_transport(std::shared_ptr<ScriptedPidJoystick> p_joystick) {
	return std::make_unique<ScriptedHidTransport>(std::move(p_joystick));
}

} // namespace haptics::pid
