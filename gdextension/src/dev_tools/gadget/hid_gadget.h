#pragma once

// A USB HID device as a FunctionFS gadget: one HID interface with an interrupt IN endpoint
// (input reports, polled by the host every 1 ms) and an interrupt OUT endpoint (output
// reports: usbhid sends them there, one per 1 ms frame, and queues the rest), answering the
// HID class requests on ep0 (the report descriptor, GET_REPORT, SET_REPORT, SET_IDLE). The
// kernel's usbhid binds it as it binds a real stick, and for PID devices starts hid-pidff.
// The model behind it is the same UhidHandler a uhid device uses.

#include "dev_tools/gadget/usb_gadget.h"
#include "dev_tools/uhid/uhid_device.h"

#include <atomic>
#include <cstdint>
#include <span>
#include <thread>
#include <vector>

namespace haptics::gadget {

// Where the device's input reports come from: the next report to send (byte 0 its ID), or 0
// for none this time.
class HidInputSource {
public:
	virtual ~HidInputSource() = default;
	virtual size_t next_input(std::span<uint8_t> r_report) = 0;
};

struct HidGadgetCounts {
	uint64_t outputs = 0; // Reports on the interrupt OUT endpoint.
	uint64_t get_reports = 0;
	uint64_t set_reports = 0;
	uint64_t inputs = 0;
};

class HidGadget final : public GadgetHandler {
public:
	HidGadget(uhid::UhidHandler &p_handler, HidInputSource &p_inputs);
	~HidGadget() override; // destroy()

	// Makes the gadget with p_descriptor as its report descriptor; plug() presents it.
	Status create(const GadgetIdentity &p_identity, std::span<const uint8_t> p_descriptor);
	Status plug() { return gadget_.plug(); }
	Status unplug() { return gadget_.unplug(); }
	void destroy();

	HidGadgetCounts counts() const;

	// A device that stops taking output (issue 38, item 5). Held, the OUT endpoint NAKs every
	// report after the one already under way (no read is waiting for it), as a busy firmware
	// does; released, it takes them again.
	void hold_outputs(bool p_hold) { hold_outputs_ = p_hold; }
	// Halts the OUT endpoint (FunctionFS halts an endpoint used in the wrong direction): each
	// later report ends in STALL until the host clears the halt. Holds the outputs first, and
	// waits up to p_wait_s for the report under way to end.
	Status stall_outputs(double p_wait_s = 2.0);

	bool on_setup(const usb_ctrlrequest &p_request, std::span<const uint8_t> p_data, std::vector<uint8_t> &r_reply) override;

private:
	void pump_inputs();
	void drain_outputs();

	uhid::UhidHandler &handler_;
	HidInputSource &inputs_;
	UsbGadget gadget_;
	std::vector<uint8_t> descriptor_;
	std::atomic<bool> running_{ false };
	std::atomic<bool> hold_outputs_{ false };
	std::atomic<bool> out_idle_{ false }; // The drain thread is held, not in a read.
	std::thread in_thread_;
	std::thread out_thread_;
	std::atomic<uint64_t> outputs_{ 0 };
	std::atomic<uint64_t> get_reports_{ 0 };
	std::atomic<uint64_t> set_reports_{ 0 };
	std::atomic<uint64_t> input_count_{ 0 };
};

} // namespace haptics::gadget
