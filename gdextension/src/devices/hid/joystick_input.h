#pragma once

// The stick a force-feedback joystick or wheel reports: its Generic Desktop X (and Y) axes,
// or Simulation Steering for a wheel without X, and its Button-page buttons, found in the
// report descriptor and decoded from input reports. Axes are normalised by their logical
// range to -1..1 (the raw centre of a 0..1023 axis is 511.5). The layout copies the fields
// it needs, so it does not depend on the descriptor's lifetime, and decoding neither
// allocates nor trusts the report: a short, foreign or garbled report is rejected.

#include "core/base/status.h"
#include "devices/hid/report_descriptor.h"

#include <cstdint>
#include <span>

namespace haptics::hid {

struct JoystickInputLayout {
	static constexpr uint32_t MAX_BUTTON_FIELDS = 4;
	static constexpr uint32_t MAX_BUTTONS = 32; // DeviceState::buttons is 32 bits.

	uint8_t report_id = 0; // 0 when the descriptor uses no report IDs.
	uint32_t report_length = 0; // On the wire, ID byte included.
	Field x; // GD X, else Simulation Steering.
	uint32_t x_index = 0;
	bool has_y = false;
	Field y;
	uint32_t y_index = 0;
	// Variable Button-page fields of the same report; element e is button bit button_bit[f][e]
	// (0xFF: not a button we report).
	uint32_t button_field_count = 0;
	Field button_fields[MAX_BUTTON_FIELDS];
	uint8_t button_bit[MAX_BUTTON_FIELDS][MAX_BUTTONS] = {};
	uint32_t button_count = 0; // Highest button number reported (<= MAX_BUTTONS).

	// The first Input report with an X (or Steering) axis. UNSUPPORTED when there is none.
	static Status find(const ReportDescriptor &p_descriptor, JoystickInputLayout &r_layout);
};

struct JoystickSample {
	double x = 0.0; // -1..1, right positive (HID X).
	double y = 0.0; // -1..1, toward the user positive (HID Y); 0 without a Y axis.
	uint32_t buttons = 0; // Bit b = button b + 1.
};

// False when p_report is not the stick's report (other report ID) or is too short for it.
bool decode_joystick_input(const JoystickInputLayout &p_layout, std::span<const uint8_t> p_report, JoystickSample &r_sample);

// Normalises p_value from the field's logical range to -1..1 (clamped); 0 for an empty range.
double normalise_axis(const Field &p_field, int64_t p_value);

} // namespace haptics::hid
