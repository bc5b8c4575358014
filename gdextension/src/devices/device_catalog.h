#pragma once

// Which devices we know how to drive. Pure and table-driven, so that supporting a new
// device is one line in device_catalog.cpp and the rules can be tested without hardware.

#include "devices/device_info.h"

#include <cstdint>
#include <string_view>

namespace haptics {

// HID usage page "Physical Interface Device": USB HID PID force feedback.
inline constexpr uint16_t HID_USAGE_PAGE_PID = 0x0F;

struct DeviceClassification {
	bool known_haptic = false;
	std::string_view model; // Points into the static catalog; empty when unknown.
};

// p_usage_page is only meaningful for HID backends; pass 0 when unknown.
DeviceClassification classify_device(std::string_view p_backend, uint16_t p_vendor_id,
		uint16_t p_product_id, uint16_t p_usage_page) noexcept;

// Fills known_haptic and model from the other fields of r_info.
void apply_catalog(DeviceInfo &r_info);

} // namespace haptics
