#pragma once

// The stick (or wheel) and buttons as evdev reports them, decoded into a deflection in
// [-1, 1] per axis and a button bitmask.
//
// Axes: EVIOCGABS gives each axis's range [minimum, maximum] and `flat`, the dead zone the
// driver declares around the centre. The deflection is (value - centre) / half-range with
// the flat band removed and the rest rescaled to reach +-1 at the ends; a flat wider than
// half the half-range is treated as a driver bug and capped there.
// Joysticks report +Y toward the user (HID: Y grows from far to near); our device space has
// y up = away from the user, so the decoded y is the NEGATED axis. x is unchanged.
//
// Buttons: bit i of the mask is the i-th key code the device has, in SDL's order: codes
// from BTN_JOYSTICK (0x120, BTN_TRIGGER / BTN_SOUTH...) up to KEY_MAX, then BTN_MISC..0x11f;
// keyboard keys (below BTN_MISC) are not buttons. So a stick's trigger and a wheel's first
// paddle are both bit 0, whatever codes their drivers chose. At most 32.
//
// Events are applied in frames: values between two SYN_REPORTs are committed together.
// SYN_DROPPED (the kernel's per-client buffer overflowed) discards events up to the next
// SYN_REPORT and asks for a resync, which reads the current values back with EVIOCGABS and
// EVIOCGKEY (the evdev protocol's recovery). Reads are whole 24-byte events from a real
// kernel; anything else (a short read from a broken transport, unknown types and codes) is
// counted and skipped, never read past.

#include "core/base/status.h"
#include "devices/evdev/evdev_abi.h"
#include "devices/evdev/evdev_syscalls.h"

#include <cstddef>
#include <cstdint>

namespace haptics::evdev {

struct AbsRange {
	int32_t value = 0;
	int32_t minimum = 0;
	int32_t maximum = 0;
	int32_t fuzz = 0;
	int32_t flat = 0;
	int32_t resolution = 0;
};

AbsRange decode_absinfo(const uint8_t *p_bytes); // INPUT_ABSINFO_SIZE bytes.
// OUT_OF_RANGE when maximum <= minimum; the message names p_axis and p_path.
Status validate_abs_range(const AbsRange &p_range, const char *p_axis, const char *p_path);
// [-1, 1]; 0 inside the flat band; 0 for an empty range.
double normalise_axis(int32_t p_value, const AbsRange &p_range);

struct EvdevButtonMap {
	static constexpr uint32_t CAPACITY = 32;
	uint16_t codes[CAPACITY] = {};
	uint32_t count = 0;
	// -1 when p_code is not a mapped button.
	int32_t bit_of(uint16_t p_code) const;
};
// From an EVIOCGBIT(EV_KEY) bitmap, in the order above.
EvdevButtonMap button_map_from_key_bits(const uint8_t *p_bits, size_t p_size);

struct EvdevInputLayout {
	uint16_t x_code = EVDEV_ABS_X;
	AbsRange x_range;
	bool has_y = true; // False for a wheel.
	uint16_t y_code = EVDEV_ABS_Y;
	AbsRange y_range;
	EvdevButtonMap buttons;
};

struct EvdevInputStats {
	uint64_t events = 0; // Whole events decoded.
	uint64_t ignored = 0; // Types/codes we do not use.
	uint64_t partial_bytes = 0; // Trailing bytes of a read that were not a whole event.
	uint64_t dropped = 0; // SYN_DROPPED seen.
};

class EvdevInputDecoder {
public:
	// Starts from the layout's ranges' current values, no buttons pressed.
	void configure(const EvdevInputLayout &p_layout);
	const EvdevInputLayout &layout() const { return layout_; }

	void feed(const uint8_t *p_bytes, size_t p_size);

	// The committed frame.
	double x() const { return normalise_axis(committed_.x, layout_.x_range); }
	double y() const { return layout_.has_y ? -normalise_axis(committed_.y, layout_.y_range) : 0.0; }
	uint32_t buttons() const { return committed_.buttons; }
	int32_t raw_x() const { return committed_.x; }
	int32_t raw_y() const { return committed_.y; }

	bool needs_resync() const { return needs_resync_; }
	// After a resync: the kernel's current values replace both frames.
	void apply_resync(int32_t p_x, int32_t p_y, uint32_t p_buttons);
	const EvdevInputStats &stats() const { return stats_; }

private:
	struct Frame {
		int32_t x = 0;
		int32_t y = 0;
		uint32_t buttons = 0;
	};
	void apply(uint16_t p_type, uint16_t p_code, int32_t p_value);

	EvdevInputLayout layout_;
	Frame pending_;
	Frame committed_;
	bool discarding_ = false; // Between SYN_DROPPED and the next SYN_REPORT.
	bool needs_resync_ = false;
	EvdevInputStats stats_;
};

inline constexpr size_t INPUT_READ_EVENTS = 64;
inline constexpr size_t INPUT_READ_BUFFER_SIZE = INPUT_READ_EVENTS * INPUT_EVENT_SIZE;
// A bounded drain: this many full buffers per call at most, so a flood of events cannot
// hold the I/O cycle (what is left is read next cycle).
inline constexpr int INPUT_MAX_READS_PER_DRAIN = 8;

// Reads every pending event into r_decoder (non-blocking), then resyncs when a SYN_DROPPED
// asked for it. 0, or -errno (-ENODEV once unplugged). r_buffer: INPUT_READ_BUFFER_SIZE
// bytes owned by the caller, so nothing is allocated.
int drain_input_events(EvdevSyscalls &r_sys, int p_fd, EvdevInputDecoder &r_decoder, uint8_t *r_buffer);
// EVIOCGABS for the axes and EVIOCGKEY for the buttons. 0 or -errno.
int resync_input(EvdevSyscalls &r_sys, int p_fd, EvdevInputDecoder &r_decoder);

} // namespace haptics::evdev
