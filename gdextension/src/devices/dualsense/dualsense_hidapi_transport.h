#pragma once

// The real transport: hidapi on Linux hidraw (HAPI-lib; docs/devices/hid.md). One hid_device opened
// by path, set non-blocking; writes are output reports, reads poll the hidraw queue.
//
// Bus: hidapi 0.13 added hid_device_info::bus_type (and hid_get_device_info on an open
// device); we use it when the headers have it, else bus() is UNKNOWN and the device infers
// the link from the first input report (dualsense_input.h bus_from_input_report).
//
// Opening (only ever a hidraw node: hidapi 0.13.1 crashes on others) and unplugged vs other
// errors are shared with the PID stick (hid/hidapi_open.h). hidapi allocates its error text
// on failures only; a successful call does not allocate.
//
// hid_init() is called at open; hid_exit() never (device enumeration calls it; on hidraw it
// only frees hidapi's global error text).

#include "devices/dualsense/dualsense_transport.h"

#include <string>

struct hid_device_;

namespace haptics::dualsense {

class HidapiTransport final : public DualSenseTransport {
public:
	explicit HidapiTransport(std::string p_path);
	~HidapiTransport() override;

	HidapiTransport(const HidapiTransport &) = delete;
	HidapiTransport &operator=(const HidapiTransport &) = delete;

	Status open() override;
	void close() override;
	bool is_open() const override { return device_ != nullptr; }
	Bus bus() const override { return bus_; }

	TransportIo write_output(const uint8_t *p_report, size_t p_size) override;
	TransportIo read_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, int p_timeout_ms = 0) override;
	TransportIo get_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size) override;

	const char *error_text() const override { return error_; }
	const char *location() const override { return path_.c_str(); }

private:
	// Records why p_call failed (hidapi's text, errno) and classifies it.
	TransportIo fail(const char *p_call, int p_errno);

	std::string path_;
	hid_device_ *device_ = nullptr;
	Bus bus_ = Bus::UNKNOWN;
	char error_[160] = {};
};

} // namespace haptics::dualsense
