#pragma once

// A HID device made in user space through the kernel's uhid driver (/dev/uhid), so that a
// software model of a device's firmware is, to the kernel and everything above it, a real
// HID device: it gets a /dev/hidraw node, hidapi enumerates and opens it, and a kernel HID
// driver (hid-playstation) binds to it. Used by the tests that run our device stack against
// a real kernel (gdextension/vm_tests, inside a VM: the host has no /dev/uhid).
//
// One thread reads the kernel's requests and hands them to the UhidHandler: what the host
// writes (Output reports), and GET_REPORT / SET_REPORT (Feature reports), which it answers.
// Input reports go the other way through send_input(). destroy() is an unplug.

#include "core/base/status.h"

#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace haptics::uhid {

// What the kernel asked the device; called on the device's own thread.
class UhidHandler {
public:
	virtual ~UhidHandler() = default;
	// An Output report as the host wrote it (byte 0 the report ID when the device uses IDs).
	virtual void on_output(std::span<const uint8_t> p_report) = 0;
	// GET_REPORT of report p_id (Feature when p_feature, else Input): fill r_reply with the
	// report (byte 0 its ID) and return true, or false to answer with an I/O error.
	virtual bool on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) = 0;
	// SET_REPORT (Feature when p_feature, else Output): true to acknowledge it.
	virtual bool on_set_report(std::span<const uint8_t> p_report, bool p_feature) = 0;
};

struct UhidIdentity {
	std::string name = "haptics test device";
	// The kernel's physical path: an input device a HID driver makes inherits it (evdev ids
	// are made from it when there is one), so each model gets its own.
	std::string phys = "haptics-uhid";
	std::string uniq; // The serial number hidraw and hidapi report; empty: none.
	uint16_t bus = 0x03; // BUS_USB.
	uint32_t vendor = 0;
	uint32_t product = 0;
	uint32_t version = 0x0100;
};

struct UhidCounts {
	uint64_t outputs = 0;
	uint64_t get_reports = 0;
	uint64_t set_reports = 0;
	uint64_t inputs = 0;
	bool started = false; // The kernel's driver started the device (UHID_START).
	bool opened = false; // Someone holds it open (UHID_OPEN without a CLOSE since).
};

class UhidDevice {
public:
	explicit UhidDevice(UhidHandler &p_handler);
	~UhidDevice(); // destroy()

	UhidDevice(const UhidDevice &) = delete;
	UhidDevice &operator=(const UhidDevice &) = delete;

	// Creates the device with p_descriptor and starts answering the kernel.
	Status create(const UhidIdentity &p_identity, std::span<const uint8_t> p_descriptor);
	// Removes the device (as unplugging it does) and stops the thread. Idempotent.
	void destroy();
	bool exists() const { return fd_ >= 0; }

	// An Input report to the host (byte 0 its ID when the device uses IDs).
	Status send_input(std::span<const uint8_t> p_report);

	UhidCounts counts() const;

private:
	void run();
	void answer_get_report(uint32_t p_id, uint8_t p_report, bool p_feature);
	void answer_set_report(uint32_t p_id, std::span<const uint8_t> p_report, bool p_feature);
	Status write_event(const void *p_event, size_t p_size);

	UhidHandler &handler_;
	int fd_ = -1;
	int wake_[2] = { -1, -1 }; // A pipe that ends the thread's poll.
	std::thread thread_;
	std::atomic<uint64_t> outputs_{ 0 };
	std::atomic<uint64_t> get_reports_{ 0 };
	std::atomic<uint64_t> set_reports_{ 0 };
	std::atomic<uint64_t> inputs_{ 0 };
	std::atomic<bool> started_{ false };
	std::atomic<bool> opened_{ false };
};

} // namespace haptics::uhid
