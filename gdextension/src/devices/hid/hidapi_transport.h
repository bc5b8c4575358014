#pragma once

// HidTransport over hidapi (the hidraw backend on Linux; docs/devices/hid.md): hid_open_path,
// hid_write (Output, interrupt OUT), hid_send_feature_report / hid_get_feature_report
// (control transfers), hid_read_timeout(..., 0) (non-blocking Input). The report descriptor
// comes from hid_get_report_descriptor on hidapi >= 0.14, else from sysfs (this machine
// has 0.13.1).
//
// open() and the unplug-or-failure verdict are shared with the DualSense (hidapi_open.h). A
// failed call is DISCONNECTED when the device is gone and FAILED otherwise; the reason is
// hidapi's message. Success paths do not allocate; hidapi itself allocates its error
// strings on failure paths only.

#include "devices/hid/hid_transport.h"

#include <string>

struct hid_device_;

namespace haptics::hid {

class HidapiTransport final : public HidTransport {
public:
	explicit HidapiTransport(std::string p_path);
	~HidapiTransport() override;

	HidapiTransport(const HidapiTransport &) = delete;
	HidapiTransport &operator=(const HidapiTransport &) = delete;

	Status open() override;
	void close() override;
	bool is_open() const override { return device_ != nullptr; }
	Status report_descriptor(std::vector<uint8_t> &r_bytes) override;

	DeviceIo write_output(std::span<const uint8_t> p_report) override;
	DeviceIo send_feature(std::span<const uint8_t> p_report) override;
	DeviceIo get_feature(std::span<uint8_t> p_buffer, size_t &r_length) override;
	DeviceIo read_input(std::span<uint8_t> p_buffer, size_t &r_length) override;
	const char *last_error() const override { return error_; }
	bool clear_halt() override;

	const std::string &path() const { return path_; }

private:
	DeviceIo failed(const char *p_call, int p_errno);

	std::string path_;
	hid_device_ *device_ = nullptr;
	char error_[192] = {};
	bool halted_ = false; // The last failure was a STALL: clear_halt() resets the device.
	size_t halt_text_length_ = 0; // error_'s part before what clear_halt() says.
};

} // namespace haptics::hid
