#include "dev_tools/gadget/falcon_gadget.h"

#include "devices/falcon/falcon_ftdi.h"

#include <unistd.h>

#include <chrono>

namespace haptics::gadget {

namespace {

constexpr uint8_t VENDOR_CLASS = 0xFF;
// The FT232's packets are 64 bytes at full speed; dummy_hcd runs at high speed, where a bulk
// endpoint's packet must be 512 bytes. The model never sends more than 64 at a time.
constexpr uint16_t FULL_SPEED_PACKET = 64;
constexpr uint16_t HIGH_SPEED_PACKET = 512;
constexpr int32_t IN_PACKET = 64;
constexpr uint32_t IN_FILE = 1;
constexpr uint32_t OUT_FILE = 2;
constexpr auto IDLE_WAIT = std::chrono::milliseconds(2);

void add_ftdi_interface(std::vector<uint8_t> &r_bytes, uint16_t p_packet) {
	add_interface(r_bytes, 2, VENDOR_CLASS, VENDOR_CLASS, VENDOR_CLASS);
	add_endpoint(r_bytes, falcon::FALCON_ENDPOINT_IN, USB_ENDPOINT_XFER_BULK, p_packet, 0);
	add_endpoint(r_bytes, falcon::FALCON_ENDPOINT_OUT, USB_ENDPOINT_XFER_BULK, p_packet, 0);
}

} // namespace

FalconGadget::FalconGadget(std::shared_ptr<falcon::ScriptedFalcon> p_falcon) :
		falcon_(std::move(p_falcon)), gadget_(*this) {}

FalconGadget::~FalconGadget() {
	destroy();
}

Status FalconGadget::create(const GadgetIdentity &p_identity) {
	GadgetFunction function;
	add_ftdi_interface(function.full_speed, FULL_SPEED_PACKET);
	function.full_speed_count = 3;
	add_ftdi_interface(function.high_speed, HIGH_SPEED_PACKET);
	function.high_speed_count = 3;
	function.endpoint_count = 2;
	const Status created = gadget_.create(p_identity, function);
	if (!created) {
		return created;
	}
	running_ = true;
	in_thread_ = std::thread(&FalconGadget::pump_in, this);
	out_thread_ = std::thread(&FalconGadget::drain_out, this);
	return Status::success();
}

Status FalconGadget::plug() {
	falcon_->replug();
	return gadget_.plug();
}

Status FalconGadget::unplug() {
	const Status unbound = gadget_.unplug();
	falcon_->unplug();
	return unbound;
}

void FalconGadget::destroy() {
	running_ = false;
	(void)unplug(); // Ends the transfers the threads wait in.
	for (std::thread *thread : { &in_thread_, &out_thread_ }) {
		if (thread->joinable()) {
			thread->join();
		}
	}
	gadget_.destroy();
}

bool FalconGadget::on_setup(const usb_ctrlrequest &p_request, std::span<const uint8_t> p_data, std::vector<uint8_t> &r_reply) {
	(void)p_data;
	if ((p_request.bRequestType & USB_TYPE_MASK) != USB_TYPE_VENDOR) {
		return false;
	}
	const usb::UsbTransfer transfer = falcon_->control_transfer(p_request.bRequestType, p_request.bRequest, p_request.wValue,
			p_request.wIndex);
	// The FTDI requests the backend sends carry no data; an IN one gets zeros, as a reset
	// chip's registers read.
	r_reply.assign(p_request.wLength, 0);
	return transfer.ok();
}

void FalconGadget::pump_in() {
	uint8_t packet[IN_PACKET];
	while (running_) {
		if (!gadget_.enabled()) {
			std::this_thread::sleep_for(IDLE_WAIT);
			continue;
		}
		const usb::UsbTransfer read = falcon_->bulk_read(falcon::FALCON_ENDPOINT_IN, packet, IN_PACKET);
		// Blocks until the host reads it.
		if (!read.ok() || ::write(gadget_.endpoint(IN_FILE), packet, static_cast<size_t>(read.transferred)) < 0) {
			std::this_thread::sleep_for(IDLE_WAIT);
		}
	}
}

void FalconGadget::drain_out() {
	uint8_t packet[HIGH_SPEED_PACKET];
	while (running_) {
		const ssize_t got = gadget_.enabled() ? ::read(gadget_.endpoint(OUT_FILE), packet, sizeof(packet)) : -1;
		if (got <= 0) {
			std::this_thread::sleep_for(IDLE_WAIT);
			continue;
		}
		(void)falcon_->bulk_write(falcon::FALCON_ENDPOINT_OUT, packet, static_cast<int32_t>(got));
	}
}

} // namespace haptics::gadget
