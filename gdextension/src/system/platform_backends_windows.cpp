#include "system/platform_backends.h"

// Windows drives every device through the common backends (hidapi, libusb, OpenHaptics):
// there is no kernel force-feedback layer of ours to reach (DirectInput's is a user-mode
// client of the same HID reports).

namespace haptics {

std::span<const BackendRow> platform_backends() {
	return {};
}

void append_platform_devices(DeviceList &) {}

} // namespace haptics
