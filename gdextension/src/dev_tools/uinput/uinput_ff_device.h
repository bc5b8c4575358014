#pragma once

// A force-feedback device made in user space through the kernel's uinput driver, so that the
// real evdev and ff-core sit between our evdev backend and a device model: /dev/input/eventN
// appears (devtmpfs makes the node; no udev needed), ff-core checks and owns the effects,
// and what reaches the device is what a kernel FFB driver would get. Used by the tests that
// run our device stack against a real kernel (gdextension/vm_tests, inside a VM: the host
// has no /dev/uinput).
//
// The device is a scripted evdev script (dev_tools/evdev: identity, axes, buttons, EV_FF
// codes, effect slots), the same the backend's unit tests use with the scripted kernel. Its
// "firmware" is this model: one thread answers ff-core's requests in uinput's handshake
// (EV_UINPUT UI_FF_UPLOAD -> UI_BEGIN_FF_UPLOAD, store, UI_END_FF_UPLOAD; UI_FF_ERASE
// likewise), takes the EV_FF events ff-core passes down (play/stop by effect id, FF_GAIN,
// FF_AUTOCENTER), records each with its bytes and renders what plays as the scripted kernel
// does (render_playing_effects). destroy() is an unplug (UI_DEV_DESTROY).

#include "core/base/status.h"
#include "dev_tools/evdev/scripted_evdev_kernel.h"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace haptics::uinput {

struct UinputRecord {
	enum class Kind : int32_t {
		UPLOAD, // ff-core's upload: `effect` as the driver gets it; `replaced` when it updates one.
		ERASE, // The slot `id` freed.
		PLAY, // EV_FF on `id`: value = repeat count, 0 stops.
		GAIN, // FF_GAIN `value`.
		AUTOCENTER, // FF_AUTOCENTER `value`.
	};
	Kind kind = Kind::UPLOAD;
	int16_t id = -1;
	int32_t value = 0;
	bool replaced = false;
	evdev::FfEffectFields effect;
	evdev::FfEffectBytes bytes{}; // UPLOAD: the 48-byte struct ff_effect received.
};

class UinputFfDevice {
public:
	explicit UinputFfDevice(evdev::ScriptedEvdevScript p_script);
	~UinputFfDevice(); // destroy()

	UinputFfDevice(const UinputFfDevice &) = delete;
	UinputFfDevice &operator=(const UinputFfDevice &) = delete;

	// Creates the input device (the script's name, ids, phys p_phys) and starts answering.
	Status create(const std::string &p_phys = "haptics-uinput/ffb");
	// UI_DEV_DESTROY, then closes /dev/uinput and stops the thread. Idempotent.
	void destroy();
	bool exists() const { return fd_ >= 0; }
	// "/dev/input/eventN" of the device; "" when not created.
	const std::string &event_path() const { return event_path_; }

	// The stick at fractions of its half-ranges in the axis frame (+y toward the user), as
	// ScriptedEvdevKernel::set_stick_axes: EV_ABS events and SYN_REPORT.
	Status set_stick_axes(double p_x, double p_y);

	// --- What the device was told (any thread) ---------------------------------------------
	std::vector<UinputRecord> records() const;
	void clear_records();
	// The newest upload of p_type since the last clear; false when none.
	bool last_upload(uint16_t p_type, UinputRecord &r_record) const;
	evdev::ScriptedRenderedForce rendered() const;
	int32_t effects_in_use() const;
	uint64_t uploads() const { return uploads_; }

private:
	struct Slot {
		bool in_use = false;
		bool playing = false;
		evdev::FfEffectFields effect;
	};

	void run();
	void answer_upload(int32_t p_request);
	void answer_erase(int32_t p_request);
	void take_event(uint16_t p_code, int32_t p_value);
	void record(UinputRecord p_record);
	Status setup(const std::string &p_phys);
	Status write_event(uint16_t p_type, uint16_t p_code, int32_t p_value);

	evdev::ScriptedEvdevScript script_;
	int fd_ = -1;
	int wake_[2] = { -1, -1 };
	std::string event_path_;
	std::thread thread_;
	mutable std::mutex mutex_;
	std::vector<Slot> slots_;
	uint16_t gain_ = 0xffff;
	std::vector<UinputRecord> records_;
	std::atomic<uint64_t> uploads_{ 0 };
};

} // namespace haptics::uinput
