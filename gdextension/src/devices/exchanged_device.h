#pragma once

// The servo-side half every device with its own I/O thread shares (device_exchange.h): the
// servo's calls only copy the latest state and command through the exchange, and report
// the I/O side's fault and statistics. Backends derive from it, set open_ and reset the
// exchange in open(), and run their DeviceIoWorker against exchange_.

#include "core/device/device.h"
#include "devices/device_exchange.h"

namespace haptics {

class ExchangedDevice : public HapticDevice {
public:
	bool is_open() const override { return open_; }
	DeviceStatus status() const override { return exchange_.status(); }
	DeviceIoStats io_stats() const override { return exchange_.stats(); }

	DeviceIo read_state(DeviceState &r_state) override {
		return open_ ? exchange_.read_state(r_state) : DeviceIo::FAILED;
	}
	DeviceIo write_force(const ForceCommand &p_command) override {
		return open_ ? exchange_.write_command(p_command) : DeviceIo::FAILED;
	}

protected:
	DeviceExchange exchange_;
	bool open_ = false;
};

} // namespace haptics
