#include "dev_tools/gadget/hid_gadget.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace haptics::gadget {

namespace {

constexpr uint8_t HID_CLASS = 0x03;
constexpr uint8_t HID_DT_HID = 0x21;
constexpr uint8_t HID_DT_REPORT = 0x22;
constexpr uint8_t HID_GET_REPORT = 0x01;
constexpr uint8_t HID_GET_IDLE = 0x02;
constexpr uint8_t HID_GET_PROTOCOL = 0x03;
constexpr uint8_t HID_SET_REPORT = 0x09;
constexpr uint8_t HID_SET_IDLE = 0x0A;
constexpr uint8_t HID_SET_PROTOCOL = 0x0B;
constexpr uint8_t HID_FEATURE_REPORT = 3;
constexpr uint16_t MAX_PACKET = 64;
constexpr uint8_t IN_ADDRESS = USB_DIR_IN | 1;
constexpr uint8_t OUT_ADDRESS = USB_DIR_OUT | 2;
// The file of each endpoint, in descriptor order.
constexpr uint32_t IN_FILE = 1;
constexpr uint32_t OUT_FILE = 2;
// While the host has not configured the device, how often the threads look again.
constexpr auto IDLE_WAIT = std::chrono::milliseconds(2);

std::vector<uint8_t> hid_class_descriptor(size_t p_report_size) {
	return { 9, HID_DT_HID, 0x11, 0x01, 0, 1, HID_DT_REPORT, static_cast<uint8_t>(p_report_size & 0xFF),
		static_cast<uint8_t>(p_report_size >> 8) };
}

// Interface, HID, IN, OUT. p_interval: 1 frame at full speed; 2^(4-1) microframes = 1 ms at
// high speed.
void add_hid_interface(std::vector<uint8_t> &r_bytes, size_t p_report_size, uint8_t p_interval) {
	add_interface(r_bytes, 2, HID_CLASS);
	const std::vector<uint8_t> hid = hid_class_descriptor(p_report_size);
	r_bytes.insert(r_bytes.end(), hid.begin(), hid.end());
	add_endpoint(r_bytes, IN_ADDRESS, USB_ENDPOINT_XFER_INT, MAX_PACKET, p_interval);
	add_endpoint(r_bytes, OUT_ADDRESS, USB_ENDPOINT_XFER_INT, MAX_PACKET, p_interval);
}

} // namespace

HidGadget::HidGadget(uhid::UhidHandler &p_handler, HidInputSource &p_inputs) :
		handler_(p_handler), inputs_(p_inputs), gadget_(*this) {}

HidGadget::~HidGadget() {
	destroy();
}

Status HidGadget::create(const GadgetIdentity &p_identity, std::span<const uint8_t> p_descriptor) {
	descriptor_.assign(p_descriptor.begin(), p_descriptor.end());
	GadgetFunction function;
	add_hid_interface(function.full_speed, descriptor_.size(), 1);
	function.full_speed_count = 4;
	add_hid_interface(function.high_speed, descriptor_.size(), 4);
	function.high_speed_count = 4;
	function.endpoint_count = 2;
	const Status created = gadget_.create(p_identity, function);
	if (!created) {
		return created;
	}
	running_ = true;
	in_thread_ = std::thread(&HidGadget::pump_inputs, this);
	out_thread_ = std::thread(&HidGadget::drain_outputs, this);
	return Status::success();
}

void HidGadget::destroy() {
	running_ = false;
	// Unbinding ends the transfers the threads wait in.
	(void)gadget_.unplug();
	for (std::thread *thread : { &in_thread_, &out_thread_ }) {
		if (thread->joinable()) {
			thread->join();
		}
	}
	gadget_.destroy();
}

HidGadgetCounts HidGadget::counts() const {
	HidGadgetCounts counts;
	counts.outputs = outputs_;
	counts.get_reports = get_reports_;
	counts.set_reports = set_reports_;
	counts.inputs = input_count_;
	return counts;
}

bool HidGadget::on_setup(const usb_ctrlrequest &p_request, std::span<const uint8_t> p_data, std::vector<uint8_t> &r_reply) {
	const uint8_t type = p_request.bRequestType & USB_TYPE_MASK;
	const uint8_t report_type = static_cast<uint8_t>(p_request.wValue >> 8);
	const auto report_id = static_cast<uint8_t>(p_request.wValue & 0xFF);
	if (type == USB_TYPE_STANDARD && p_request.bRequest == USB_REQ_GET_DESCRIPTOR) {
		if (report_type == HID_DT_REPORT) {
			r_reply = descriptor_;
			return true;
		}
		if (report_type == HID_DT_HID) {
			r_reply = hid_class_descriptor(descriptor_.size());
			return true;
		}
		return false;
	}
	if (type != USB_TYPE_CLASS) {
		return false;
	}
	switch (p_request.bRequest) {
		case HID_GET_REPORT:
			++get_reports_;
			return handler_.on_get_report(report_id, report_type == HID_FEATURE_REPORT, r_reply);
		case HID_SET_REPORT:
			++set_reports_;
			return handler_.on_set_report(p_data, report_type == HID_FEATURE_REPORT);
		case HID_SET_IDLE:
		case HID_SET_PROTOCOL:
			return true;
		case HID_GET_IDLE:
		case HID_GET_PROTOCOL:
			r_reply = { 0 };
			return true;
		default:
			return false;
	}
}

void HidGadget::pump_inputs() {
	uint8_t report[MAX_PACKET];
	while (running_) {
		const size_t length = gadget_.enabled() ? inputs_.next_input(report) : 0;
		// Blocks until the host polls: the host's polling paces the device, as on a wire.
		if (length == 0 || ::write(gadget_.endpoint(IN_FILE), report, length) != static_cast<ssize_t>(length)) {
			std::this_thread::sleep_for(IDLE_WAIT);
			continue;
		}
		++input_count_;
	}
}

Status HidGadget::stall_outputs(double p_wait_s) {
	hold_outputs_ = true;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_wait_s);
	while (!out_idle_ && std::chrono::steady_clock::now() < deadline) {
		std::this_thread::sleep_for(IDLE_WAIT);
	}
	if (!out_idle_) {
		return Status::error(StatusCode::DEVICE_ERROR, "gadget: the OUT endpoint's read did not end within %.1f s", p_wait_s);
	}
	const uint8_t byte = 0;
	if (::write(gadget_.endpoint(OUT_FILE), &byte, 1) >= 0 || errno != EBADMSG) {
		return Status::error(StatusCode::DEVICE_ERROR, "gadget: writing the OUT endpoint did not halt it (%s)", std::strerror(errno));
	}
	return Status::success();
}

void HidGadget::drain_outputs() {
	uint8_t report[MAX_PACKET];
	while (running_) {
		out_idle_ = hold_outputs_.load();
		if (out_idle_) {
			std::this_thread::sleep_for(IDLE_WAIT);
			continue;
		}
		const ssize_t got = gadget_.enabled() ? ::read(gadget_.endpoint(OUT_FILE), report, sizeof(report)) : -1;
		if (got <= 0) {
			std::this_thread::sleep_for(IDLE_WAIT);
			continue;
		}
		++outputs_;
		handler_.on_output(std::span<const uint8_t>(report, static_cast<size_t>(got)));
	}
}

} // namespace haptics::gadget
