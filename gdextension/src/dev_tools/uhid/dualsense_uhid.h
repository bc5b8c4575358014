#pragma once

// The scripted DualSense (dev_tools/dualsense) as a real HID device of the kernel's, through
// uhid, on USB: 054C:0CE6, so the kernel's hid-playstation binds it (it reads feature reports
// 0x09, 0x20 and 0x05, makes the gamepad's evdev node with rumble, and writes its own output
// reports: LEDs at bind, rumble for evdev effects) and /dev/hidraw* is ours to open beside it.
// The pad model answers everything the kernel passes on: output reports (the kernel's and
// hidraw writers' alike), feature GET_REPORTs; its stick goes up as input reports.
//
// Every output report that reached the pad is also kept here (the newest OUTPUT_LOG_SIZE),
// readable while the pad runs: the model's own history is only for single-threaded tests.

#include "dev_tools/dualsense/scripted_dualsense.h"
#include "dev_tools/uhid/uhid_device.h"

#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace haptics::uhid {

// The pad's identity on USB: Sony's ids, the name a real pad reports.
UhidIdentity dualsense_usb_identity();
// A report descriptor for the pad on USB: a gamepad collection with input report 0x01 (63
// bytes after the ID, as PS-K's dualsense_input_report), output report 0x02 (47, the common
// block) and the feature reports the model answers (0x05, 0x09, 0x20, sized as
// hid-playstation reads them). Written for this model, not a dump of a real pad's.
std::span<const uint8_t> dualsense_usb_descriptor();

class DualSenseUhidPad final : public UhidHandler {
public:
	static constexpr size_t OUTPUT_LOG_SIZE = 512;

	// Input reports every p_input_period_ms (0: none). The real pad sends one every 4 ms;
	// the default is slower because the VM emulates every instruction hid-playstation spends
	// on one (three input devices' events each).
	explicit DualSenseUhidPad(std::shared_ptr<dualsense::ScriptedDualSense> p_pad, int p_input_period_ms = 8);
	~DualSenseUhidPad() override; // unplug()

	// Plugs the pad in: a new host session for the model, then the kernel's device.
	Status plug(const UhidIdentity &p_identity = dualsense_usb_identity());
	// Removes it from the kernel (as pulling the cable does). Idempotent.
	void unplug();
	bool plugged() const { return device_.exists(); }
	const UhidDevice &device() const { return device_; }
	dualsense::ScriptedDualSense &pad() { return *pad_; }

	// The feature report IDs the kernel asked for since plug(), in order.
	std::vector<uint8_t> features_asked() const;
	// The output reports since the last clear (oldest first), as the pad received them.
	std::vector<std::vector<uint8_t>> outputs() const;
	void clear_outputs();

	void on_output(std::span<const uint8_t> p_report) override;
	bool on_get_report(uint8_t p_id, bool p_feature, std::vector<uint8_t> &r_reply) override;
	bool on_set_report(std::span<const uint8_t> p_report, bool p_feature) override;

private:
	void pump_inputs();

	std::shared_ptr<dualsense::ScriptedDualSense> pad_;
	UhidDevice device_;
	int input_period_ms_;
	// The model is written for one transport thread at a time; here the uhid thread and the
	// input pump share it.
	mutable std::mutex mutex_;
	std::vector<uint8_t> features_asked_;
	std::deque<std::vector<uint8_t>> outputs_;
	std::atomic<bool> pumping_{ false };
	std::thread pump_;
};

} // namespace haptics::uhid
