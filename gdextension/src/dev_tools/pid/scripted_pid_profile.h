#pragma once

// Internal to the scripted PID joystick (scripted_pid_*.cpp): the firmware's fixed report
// layout, so the model and its firmware share one definition.

#include "dev_tools/pid/scripted_pid_joystick.h"

#include <cstdint>

namespace haptics::pid {

inline constexpr uint8_t NO_AXIS = 0xFF; // Profile::y_offset of a one-axis stick.

// Fixed byte offsets as each firmware reads them (byte 0 = report ID), written from
// docs/devices/hid-pid.md, "Field layouts" (AJ) and virtual_pid_descriptor.h (ours) by hand:
// deliberately not from the parser.
struct ScriptedPidJoystick::Profile {
	uint8_t input_id, input_length, buttons_offset, button_bytes, x_offset, y_offset, state_id;
	uint8_t set_effect_id, set_effect_length, se_block, se_type, se_duration, se_gain, se_enable, se_direction;
	bool direction_16bit;
	double degrees_per_direction_unit;
	uint8_t constant_id, constant_length;
	int32_t magnitude_max;
	uint8_t operation_id, free_id, control_id, gain_id;
	bool control_bitmask;
	uint8_t create_id, create_length, block_load_id, block_load_length, pool_id, pool_length;
	uint16_t infinite_a, infinite_b;
};

} // namespace haptics::pid
