#pragma once

// The scripted Falcon (dev_tools/falcon) as a USB device of the kernel's: a FunctionFS gadget
// with the Falcon's FTDI ids (0403:cb48), one vendor-class interface with a bulk IN (0x81)
// and a bulk OUT (0x02) endpoint as the FT232 has, and the FTDI vendor requests on ep0. The
// model answers as the chip and the Falcon's loader and firmware do; libusb on the host side
// finds, opens and claims it as it would the real one. Like the chip, the gadget always has
// an IN packet ready (the two status bytes, and whatever the firmware queued), so the host
// polls as it must on hardware.

#include "dev_tools/falcon/scripted_falcon.h"
#include "dev_tools/gadget/usb_gadget.h"

#include <atomic>
#include <memory>
#include <thread>

namespace haptics::gadget {

class FalconGadget final : public GadgetHandler {
public:
	explicit FalconGadget(std::shared_ptr<falcon::ScriptedFalcon> p_falcon);
	~FalconGadget() override; // destroy()

	Status create(const GadgetIdentity &p_identity);
	// Power and cable: the model powers up afresh (its loader, no firmware) when plugged.
	Status plug();
	Status unplug();
	void destroy();

	bool on_setup(const usb_ctrlrequest &p_request, std::span<const uint8_t> p_data, std::vector<uint8_t> &r_reply) override;

private:
	void pump_in();
	void drain_out();

	std::shared_ptr<falcon::ScriptedFalcon> falcon_;
	UsbGadget gadget_;
	std::atomic<bool> running_{ false };
	std::thread in_thread_;
	std::thread out_thread_;
};

} // namespace haptics::gadget
