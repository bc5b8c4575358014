#include "system/platform_backends.h"

#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_enumeration.h"
#include "system/device_open.gen.h"

namespace haptics {

namespace {

Status open_evdev(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device) {
	return evdev::open_device(p_info, r_device, evdev::EvdevTakeover{ p_options.take_gain, p_options.spring_off });
}

// When the kernel's PID driver is bound to a HID stick the hid-pid row says so, and this
// one drives the same stick.
constexpr BackendRow LINUX_BACKENDS[] = {
	{ DRIVER_EVDEV, evdev::probe, open_evdev },
};

} // namespace

std::span<const BackendRow> platform_backends() {
	return LINUX_BACKENDS;
}

void append_platform_devices(DeviceList &r_list) {
	// The kernel's force-feedback drivers (hid-pidff, wheel drivers) own most FFB devices
	// and expose them here, not on hidraw.
	evdev::enumerate_evdev_devices(r_list.devices, r_list.warnings);
}

} // namespace haptics
