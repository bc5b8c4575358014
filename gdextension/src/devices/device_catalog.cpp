#include "devices/device_catalog.h"

#include <array>
#include <optional>

namespace haptics {

namespace {

// An unset field matches anything. The first matching row wins, so specific rows
// (exact VID:PID) go before generic ones (a whole usage page).
struct CatalogEntry {
	std::string_view backend = {}; // Empty: any backend.
	std::optional<uint16_t> vendor_id = {};
	std::optional<uint16_t> product_id = {};
	std::optional<uint16_t> usage_page = {};
	std::string_view model = {};
};

constexpr std::array CATALOG{
	CatalogEntry{ .backend = BACKEND_SIMULATED, .model = SIMULATED_DEVICE_MODEL },
	CatalogEntry{ .vendor_id = 0x0403, .product_id = 0xcb48, .model = "Novint Falcon" },
	CatalogEntry{ .vendor_id = 0x054c, .product_id = 0x0ce6, .model = "Sony DualSense" },
	// Usage pages exist only in HID report descriptors, so this row cannot match libusb.
	CatalogEntry{ .backend = BACKEND_HIDAPI, .usage_page = HID_USAGE_PAGE_PID, .model = "HID PID force-feedback device" },
};

constexpr bool matches(const std::optional<uint16_t> &p_expected, uint16_t p_value) {
	return !p_expected || *p_expected == p_value;
}

} // namespace

DeviceClassification classify_device(std::string_view p_backend, uint16_t p_vendor_id,
		uint16_t p_product_id, uint16_t p_usage_page) noexcept {
	for (const CatalogEntry &entry : CATALOG) {
		if ((entry.backend.empty() || entry.backend == p_backend) &&
				matches(entry.vendor_id, p_vendor_id) && matches(entry.product_id, p_product_id) &&
				matches(entry.usage_page, p_usage_page)) {
			return { true, entry.model };
		}
	}
	return {};
}

void apply_catalog(DeviceInfo &r_info) {
	const DeviceClassification classification = classify_device(
			r_info.backend, r_info.vendor_id, r_info.product_id, r_info.usage_page);
	r_info.known_haptic = classification.known_haptic;
	r_info.model = classification.model;
}

} // namespace haptics
