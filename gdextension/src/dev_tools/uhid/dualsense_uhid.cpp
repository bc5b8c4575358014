#include "dev_tools/uhid/dualsense_uhid.h"

#include "devices/dualsense/dualsense_backend.h"

#include <chrono>

namespace haptics::uhid {

namespace {

// clang-format off
constexpr uint8_t DESCRIPTOR[] = {
	0x05, 0x01, // Usage Page (Generic Desktop)
	0x09, 0x05, // Usage (Game Pad)
	0xA1, 0x01, // Collection (Application)
	0x85, 0x01, //   Report ID (1): the input report
	0x09, 0x30, 0x09, 0x31, 0x09, 0x32, 0x09, 0x35, 0x09, 0x33, 0x09, 0x34, // X, Y, Z, Rz, Rx, Ry
	0x15, 0x00, 0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x06, 0x81, 0x02, // 6 x 8 bits, Input
	0x06, 0x00, 0xFF, 0x09, 0x20, 0x95, 0x01, 0x81, 0x02, // Vendor: the sequence byte
	0x05, 0x01, 0x09, 0x39, 0x15, 0x00, 0x25, 0x07, 0x35, 0x00, 0x46, 0x3B, 0x01, 0x65, 0x14,
	0x75, 0x04, 0x95, 0x01, 0x81, 0x42, // Hat switch, 4 bits, null state
	0x65, 0x00, // Unit (none)
	0x05, 0x09, 0x19, 0x01, 0x29, 0x0F, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x0F, 0x81, 0x02, // 15 buttons
	0x06, 0x00, 0xFF, 0x09, 0x21, 0x95, 0x0D, 0x81, 0x02, // Vendor: 13 bits
	0x09, 0x22, 0x15, 0x00, 0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x34, 0x81, 0x02, // Vendor: 52 bytes
	0x85, 0x02, 0x09, 0x23, 0x95, 0x2F, 0x91, 0x02, // Report ID (2): 47 bytes, Output
	0x85, 0x05, 0x09, 0x33, 0x95, 0x28, 0xB1, 0x02, // Report ID (5): 40 bytes, Feature
	0x85, 0x09, 0x09, 0x24, 0x95, 0x13, 0xB1, 0x02, // Report ID (9): 19 bytes, Feature
	0x85, 0x20, 0x09, 0x26, 0x95, 0x3F, 0xB1, 0x02, // Report ID (0x20): 63 bytes, Feature
	0xC0, // End Collection
};
// clang-format on

} // namespace

UhidIdentity dualsense_usb_identity() {
	UhidIdentity identity;
	identity.name = "Sony Interactive Entertainment DualSense Wireless Controller";
	identity.phys = "haptics-uhid/dualsense";
	identity.vendor = dualsense::SONY_VENDOR_ID;
	identity.product = dualsense::DUALSENSE_PRODUCT_ID;
	identity.version = 0x0100;
	return identity;
}

std::span<const uint8_t> dualsense_usb_descriptor() {
	return DESCRIPTOR;
}

DualSenseUhidPad::DualSenseUhidPad(std::shared_ptr<dualsense::ScriptedDualSense> p_pad, int p_input_period_ms) :
		pad_(std::move(p_pad)), device_(*this), input_period_ms_(p_input_period_ms) {}

DualSenseUhidPad::~DualSenseUhidPad() {
	unplug();
}

Status DualSenseUhidPad::plug(const UhidIdentity &p_identity) {
	{
		const std::lock_guard lock(mutex_);
		features_asked_.clear();
		pad_->replug();
		pad_->begin_session();
	}
	const Status created = device_.create(p_identity, DESCRIPTOR);
	if (created && input_period_ms_ > 0) {
		pumping_ = true;
		pump_ = std::thread(&DualSenseUhidPad::pump_inputs, this);
	}
	return created;
}

void DualSenseUhidPad::unplug() {
	pumping_ = false;
	if (pump_.joinable()) {
		pump_.join();
	}
	device_.destroy();
}

std::vector<uint8_t> DualSenseUhidPad::features_asked() const {
	const std::lock_guard lock(mutex_);
	return features_asked_;
}

std::vector<std::vector<uint8_t>> DualSenseUhidPad::outputs() const {
	const std::lock_guard lock(mutex_);
	return { outputs_.begin(), outputs_.end() };
}

void DualSenseUhidPad::clear_outputs() {
	const std::lock_guard lock(mutex_);
	outputs_.clear();
}

void DualSenseUhidPad::on_output(std::span<const uint8_t> p_report) {
	const std::lock_guard lock(mutex_);
	const char *error = "";
	(void)pad_->receive_output(p_report.data(), p_report.size(), error);
	outputs_.emplace_back(p_report.begin(), p_report.end());
	if (outputs_.size() > OUTPUT_LOG_SIZE) {
		outputs_.pop_front();
	}
}

bool DualSenseUhidPad::on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) {
	if (!p_feature) {
		return false;
	}
	const std::lock_guard lock(mutex_);
	features_asked_.push_back(p_id);
	uint8_t buffer[dualsense::FEATURE_MAX_SIZE];
	size_t size = 0;
	const char *error = "";
	if (pad_->produce_feature(p_id, buffer, sizeof(buffer), size, error) != dualsense::TransportIo::OK) {
		return false;
	}
	r_reply.assign(buffer, buffer + size);
	return true;
}

bool DualSenseUhidPad::on_set_report(std::span<const uint8_t> p_report, bool p_feature) {
	// The pad takes output reports this way too (hidapi never sends them so on hidraw); no
	// feature report is ours to set.
	if (p_feature) {
		return false;
	}
	on_output(p_report);
	return true;
}

void DualSenseUhidPad::pump_inputs() {
	uint8_t buffer[dualsense::MAX_INPUT_SIZE];
	while (pumping_) {
		size_t size = 0;
		{
			const std::lock_guard lock(mutex_);
			const char *error = "";
			// The model answers NO_DATA after each report (a drained queue): ask again.
			for (int attempt = 0; attempt < 2 && size == 0; ++attempt) {
				if (pad_->produce_input(buffer, sizeof(buffer), size, error) != dualsense::TransportIo::OK) {
					size = 0;
				}
			}
		}
		if (size > 0) {
			(void)device_.send_input(std::span<const uint8_t>(buffer, size));
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(input_period_ms_));
	}
}

} // namespace haptics::uhid
