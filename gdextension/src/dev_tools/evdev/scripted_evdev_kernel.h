#pragma once

// A software model of the kernel's evdev side of one force-feedback device, answering the
// EvdevSyscalls seam the way drivers/input/evdev.c and ff-core.c do, so the backend is
// tested byte for byte without hardware (and the headless Godot test and the benchmark
// drive it too):
//  - open() of the scripted path gives an fd (or the scripted errno, e.g. EACCES);
//  - EVIOCGBIT(EV_FF / EV_ABS / EV_KEY / 0), EVIOCGABS, EVIOCGNAME, EVIOCGID, EVIOCGKEY and
//    EVIOCGEFFECTS answer from the script, copying at most the size the request encodes and
//    returning the count where the kernel does;
//  - EV_FF bits as ff-core shows them: the script's codes (the driver's), plus FF_RUMBLE
//    wherever they include FF_PERIODIC (input_ff_create emulates rumble with periodic
//    effects, so a PID stick offers it too);
//  - EVIOCSFF with id -1 allocates a slot and writes the id back into the caller's struct;
//    with an id it updates that slot (-EINVAL for a slot not in use or another type or
//    waveform, -EACCES for another fd's); a type the device does not advertise, or a waveform,
//    is -EINVAL; a rumble the driver does not take itself is stored as ff-core hands it to the
//    driver (compat_effect: a 50 ms FF_SINE of strong / 3 + weak / 6); EVIOCRMFF takes the
//    id by value and frees (stops) it;
//  - write() takes whole 24-byte events: EV_FF FF_GAIN / FF_AUTOCENTER / effect id with a
//    repeat count (0 stops), ignored when out of range like the kernel;
//  - read() returns queued events whole (per fd, like evdev clients), -EAGAIN when none; a
//    full queue is replaced by SYN_DROPPED;
//  - set_plugged(false) makes every open fd answer -ENODEV (close still succeeds) and open()
//    -ENOENT; replugging is a new device: old fds stay dead;
//  - closing an fd stops and erases the effects it uploaded (input_ff_flush: effects belong
//    to the file), so a client that opens the node again starts with none of its own.
// Every call is recorded with its bytes (set_recording(false) for benchmarks; counters are
// kept either way), and rendered() computes the force the device would render.
// Thread-safe: the device's I/O thread and the test thread share it (one mutex).

#include "devices/evdev/evdev_ff.h"
#include "devices/evdev/evdev_input.h"
#include "devices/evdev/evdev_syscalls.h"

#include <deque>
#include <mutex>
#include <string>
#include <vector>

namespace haptics::evdev {

struct ScriptedAbsAxis {
	uint16_t code = 0;
	AbsRange range;
};

struct ScriptedEvdevScript {
	std::string path = "/dev/input/event7";
	std::string name;
	uint16_t bustype = 0x0003; // BUS_USB
	uint16_t vendor = 0;
	uint16_t product = 0;
	uint16_t version = 0;
	std::vector<uint16_t> ff_codes; // EV_FF bits (effect types, FF_GAIN, FF_AUTOCENTER).
	std::vector<ScriptedAbsAxis> axes;
	std::vector<uint16_t> key_codes;
	int32_t max_effects = 10;
	int open_error = 0; // A positive errno open() fails with (EACCES), or 0.
	size_t buffer_events = 256; // Per-fd queue; beyond it the kernel reports SYN_DROPPED.
};

// An Arduino Leonardo running the ArduinoJoystickWithFFBLibrary PID firmware (docs/devices/hid-pid.md, "AJ's descriptor")
// under hid-pidff: 2341:8036, X/Y in [-32767, 32767], FF_CONSTANT and the other PID effects,
// FF_GAIN, 4 buttons from BTN_TRIGGER.
ScriptedEvdevScript scripted_joystick_script();
// A wheel: ABS_WHEEL in [0, 65535], FF_CONSTANT, FF_GAIN, FF_AUTOCENTER, 2 paddles
// (BTN_SOUTH, BTN_EAST).
ScriptedEvdevScript scripted_wheel_script();
// A DualSense's gamepad node under hid-playstation: 054C:0CE6, sticks in [0, 255], rumble
// through ff-memless (FF_RUMBLE; FF_PERIODIC with square, triangle and sine, FF_GAIN, 16
// effects: what memless adds), no constant force.
ScriptedEvdevScript scripted_gamepad_script();

struct ScriptedEvdevCall {
	enum class Kind : int32_t {
		OPEN,
		IOCTL,
		WRITE,
		READ,
		CLOSE,
	};
	Kind kind = Kind::OPEN;
	int fd = -1;
	uint32_t request = 0; // IOCTL only.
	// OPEN: the path. IOCTL: the argument as the kernel received it (_IOC_WRITE; EVIOCRMFF's
	// id as a 4-byte int) or as it answered (_IOC_READ). WRITE/READ: the bytes moved.
	std::vector<uint8_t> bytes;
	int64_t result = 0; // The return value (>= 0) or -errno.
};

struct ScriptedEvdevCounters {
	uint64_t ioctls = 0;
	uint64_t ioctl_bytes = 0; // Argument bytes, both ways.
	uint64_t writes = 0;
	uint64_t write_bytes = 0;
	uint64_t reads = 0; // Including -EAGAIN.
	uint64_t read_bytes = 0;
	uint64_t uploads = 0; // Successful EVIOCSFF.
};

// The force the device renders now, as the firmwares of docs/devices/hid-pid.md ("Direction")
// do: the sum over the
// playing FF_CONSTANT effects of level / 0x7FFF * gain / 0xFFFF along (sin t, -cos t), t the
// direction, in the stick's axis frame (+x right, +y toward the user); fractions of full.
// Rumble as ff-memless combines it: the playing FF_RUMBLE effects' magnitudes, each scaled by
// the gain, summed and clamped to 0xFFFF; periodic effects (a converted rumble among them)
// are counted with the last one's magnitude.
struct ScriptedRenderedForce {
	int32_t playing = 0; // Constant effects playing.
	double axis_x = 0.0;
	double axis_y = 0.0;
	uint16_t direction = 0; // Of the last playing effect.
	int16_t level = 0;
	uint16_t gain = 0xffff;
	int32_t rumbles_playing = 0;
	uint16_t rumble_strong = 0;
	uint16_t rumble_weak = 0;
	int32_t periodic_playing = 0;
	int16_t periodic_magnitude = 0;
};

// What a device playing p_playing at p_gain renders (the rules above); shared with the
// uinput model (dev_tools/uinput), which plays what the real kernel hands it.
ScriptedRenderedForce render_playing_effects(const std::vector<FfEffectFields> &p_playing, uint16_t p_gain);

class ScriptedEvdevKernel final : public EvdevSyscalls {
public:
	explicit ScriptedEvdevKernel(ScriptedEvdevScript p_script = scripted_joystick_script());

	int open_device(const char *p_path) override;
	int ioctl(int p_fd, uint32_t p_request, void *p_arg) override;
	int64_t write(int p_fd, const void *p_bytes, size_t p_size) override;
	int64_t read(int p_fd, void *r_bytes, size_t p_capacity) override;
	int close(int p_fd) override;

	// --- The script (any thread) ----------------------------------------------------------
	void set_plugged(bool p_plugged);
	bool plugged() const;
	// An EV_ABS event to every open fd (no SYN_REPORT) and the value EVIOCGABS reports.
	void set_axis(uint16_t p_code, int32_t p_value);
	void set_button(uint16_t p_code, bool p_pressed);
	void sync(); // EV_SYN SYN_REPORT.
	// The stick at fractions of its half-ranges in the AXIS frame (+y toward the user), then
	// SYN_REPORT. A wheel script takes p_x for its wheel axis and ignores p_y.
	void set_stick_axes(double p_x, double p_y);
	// The next read() on each open fd returns exactly these bytes (even a partial event).
	void queue_raw_read(const std::vector<uint8_t> &p_bytes);
	// The next matching call fails with -p_error (request 0 = any ioctl).
	void fail_next_ioctl(uint32_t p_request, int p_error);
	void fail_next_write(int p_error);
	void fail_next_read(int p_error);

	// --- What happened ----------------------------------------------------------------------
	void set_recording(bool p_recording);
	std::vector<ScriptedEvdevCall> calls() const;
	void clear_calls();
	ScriptedEvdevCounters counters() const;
	ScriptedRenderedForce rendered() const;
	int32_t effects_in_use() const;
	int32_t autocenter() const; // Last FF_AUTOCENTER written; -1 if never.
	int32_t open_fds() const;
	const ScriptedEvdevScript &script() const { return script_; }

private:
	struct Chunk {
		std::vector<uint8_t> bytes;
		size_t offset = 0;
		bool raw = false;
	};
	struct Client {
		int fd = -1;
		bool alive = true;
		std::deque<Chunk> queue;
		size_t queued_events = 0;
	};
	struct Slot {
		bool in_use = false;
		int owner_fd = -1;
		FfEffectFields effect;
		bool playing = false;
	};

	Client *find_client(int p_fd);
	void record(ScriptedEvdevCall::Kind p_kind, int p_fd, uint32_t p_request, const void *p_bytes, size_t p_size,
			int64_t p_result);
	void post_event(uint16_t p_type, uint16_t p_code, int32_t p_value);
	void reset_device();
	bool has(const std::vector<uint16_t> &p_codes, uint16_t p_code) const;
	bool advertises(uint16_t p_code) const; // EV_FF bits as ff-core shows them.
	AbsRange *axis(uint16_t p_code);
	int ioctl_locked(Client &r_client, uint32_t p_request, void *p_arg, size_t &r_answered);
	int upload(Client &r_client, uint8_t *r_effect);
	int erase(Client &r_client, int p_id);
	int copy_bits(uint32_t p_event_type, uint8_t *r_out, size_t p_size) const;
	void handle_event(const InputEvent &p_event);

	ScriptedEvdevScript script_;
	mutable std::mutex mutex_;
	bool plugged_ = true;
	bool recording_ = true;
	int next_fd_ = 40;
	std::vector<Client> clients_;
	std::vector<Slot> slots_;
	std::vector<uint16_t> keys_down_;
	uint16_t gain_ = 0xffff;
	int32_t autocenter_ = -1;
	uint64_t event_clock_ = 0;
	uint32_t fail_ioctl_request_ = 0;
	int fail_ioctl_error_ = 0;
	int fail_write_error_ = 0;
	int fail_read_error_ = 0;
	std::vector<ScriptedEvdevCall> calls_;
	ScriptedEvdevCounters counters_;
};

} // namespace haptics::evdev
