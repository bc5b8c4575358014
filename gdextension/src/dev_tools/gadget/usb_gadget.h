#pragma once

// A USB device made in user space: a configfs gadget with one FunctionFS function, bound to a
// USB device controller (dummy_hcd's, inside the VM tests' kernel), so that a software model
// of a device's firmware is a real USB device to the kernel on the other side of the
// controller: usbhid, hid-pidff and libusb see a device they enumerate, configure and talk
// to over real control, interrupt and bulk transfers. Needs configfs, usb_f_fs and a UDC:
// only the VM tests use it (the host has no USB bus).
//
// One thread answers ep0: the control requests the host sends the function (with
// FUNCTIONFS_ALL_CTRL_RECIP, class and vendor requests to the device as well), which the
// GadgetHandler answers. The data endpoints are files (ep1, ep2, ... in descriptor order)
// that the model's own threads read and write; they block until the host moves data.
// plug() and unplug() bind and unbind the controller, as a cable does.

#include "core/base/status.h"

#include <linux/usb/ch9.h>

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace haptics::gadget {

class GadgetHandler {
public:
	virtual ~GadgetHandler() = default;
	// A control request. Device-to-host (bRequestType & USB_DIR_IN): fill r_reply (cut to
	// wLength). Host-to-device: p_data is the data stage. false stalls the request.
	virtual bool on_setup(const usb_ctrlrequest &p_request, std::span<const uint8_t> p_data, std::vector<uint8_t> &r_reply) = 0;
	// The host configured the device (endpoints usable) or deconfigured / lost it.
	virtual void on_enabled(bool p_enabled) { (void)p_enabled; }
};

struct GadgetIdentity {
	uint16_t vendor = 0;
	uint16_t product = 0;
	uint16_t device_release = 0x0100; // bcdDevice
	std::string manufacturer = "haptics";
	std::string product_name = "haptics test gadget";
	std::string serial = "0001";
};

// One interface's descriptors (interface, class-specific, endpoints), full and high speed.
struct GadgetFunction {
	std::vector<uint8_t> full_speed;
	uint32_t full_speed_count = 0; // How many descriptors full_speed holds.
	std::vector<uint8_t> high_speed;
	uint32_t high_speed_count = 0;
	uint32_t endpoint_count = 0;
};

class UsbGadget {
public:
	explicit UsbGadget(GadgetHandler &p_handler);
	~UsbGadget(); // destroy()

	UsbGadget(const UsbGadget &) = delete;
	UsbGadget &operator=(const UsbGadget &) = delete;

	// Makes the gadget (configfs), mounts its FunctionFS, writes the descriptors, opens the
	// endpoint files and starts answering ep0. Not yet plugged in.
	Status create(const GadgetIdentity &p_identity, const GadgetFunction &p_function);
	// Binds the first USB device controller: the host sees the device arrive.
	Status plug();
	// Unbinds it: the host sees the device leave; the endpoints' transfers end.
	Status unplug();
	// Unplugs and removes everything create() made. Idempotent.
	void destroy();

	bool enabled() const { return enabled_; }
	// The file of data endpoint p_index (1-based, as ep1, ep2, ...); -1 when absent.
	int endpoint(uint32_t p_index) const;
	uint64_t setups() const { return setups_; }

private:
	void run();
	void answer(const usb_ctrlrequest &p_request);
	Status write_descriptors(const GadgetFunction &p_function);

	GadgetHandler &handler_;
	std::string name_;
	std::string configfs_;
	std::string mount_;
	int ep0_ = -1;
	std::vector<int> endpoints_;
	int wake_[2] = { -1, -1 };
	std::thread thread_;
	std::atomic<bool> enabled_{ false };
	std::atomic<uint64_t> setups_{ 0 };
	bool plugged_ = false;
};

// Descriptor builders for GadgetFunction.
void add_interface(std::vector<uint8_t> &r_bytes, uint8_t p_endpoints, uint8_t p_class, uint8_t p_subclass = 0,
		uint8_t p_protocol = 0);
void add_endpoint(std::vector<uint8_t> &r_bytes, uint8_t p_address, uint8_t p_attributes, uint16_t p_max_packet,
		uint8_t p_interval);

} // namespace haptics::gadget
