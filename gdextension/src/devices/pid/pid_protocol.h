#pragma once

// PID report encoding and decoding, pure bytes (no I/O), byte-exact with what the Linux
// hid-pidff driver writes for the same request (docs/devices/hid-pid.md: "Value scaling", "The
// kernel's report sequences", "Expected bytes"), so a device that
// works under Linux sees the same reports from us.
//
// Inputs use the Linux input units: direction u16 0..0xFFFF for 0..360° (0x4000 = 90°),
// level s16, gain u16. The scaling to each device's logical ranges is the kernel's, with
// C integer division (truncation toward zero), in 64 bits as K-new:
//   rescale(v, max)      = v * (Lmax - Lmin) / max + Lmin
//   signed level (Lmin<0) = v > 0 ? v * Lmax / 0x7FFF : v < 0 ? v * Lmin / -0x8000 : 0
//   signed level (Lmin>=0)= v < 0 ? rescale(-v, 0x8000) : rescale(v, 0x7FFF)
// e.g. direction 0x4000 -> 63 on 0..255, 9000 on 0..36000; level +0x4000 -> 5000 on
// +-10000, -0x4000 -> -16383 on +-32767 (truncation asymmetry).
//
// Encoders return false only when a value cannot be represented in its field, which a
// layout that PidLayout::build accepted and the clamping here prevent; callers still check.

#include "devices/pid/pid_layout.h"

#include <cstdint>
#include <span>

namespace haptics::pid {

// One report on the wire, byte 0 = report ID, in a fixed buffer (no allocation).
struct PidReport {
	uint8_t bytes[PID_MAX_REPORT_BYTES] = {};
	uint16_t length = 0;
	std::span<const uint8_t> view() const { return std::span<const uint8_t>(bytes, length); }
	std::span<uint8_t> data() { return std::span<uint8_t>(bytes, length); }
};

int64_t rescale(int64_t p_value, int64_t p_max, const hid::Field &p_field);
int64_t scale_direction(uint16_t p_direction, const hid::Field &p_field);
int64_t scale_signed(int16_t p_level, const hid::Field &p_field);
int64_t scale_unsigned(uint16_t p_value, const hid::Field &p_field);

enum class EffectOperation : uint8_t {
	START,
	START_SOLO,
	STOP,
};

enum class DeviceCommand : uint8_t {
	ENABLE_ACTUATORS,
	DISABLE_ACTUATORS,
	STOP_ALL_EFFECTS,
	RESET,
	PAUSE,
	CONTINUE,
};
const char *device_command_name(DeviceCommand p_command);

// A zeroed report of that layout report index with its ID byte set.
void begin_report(const PidLayout &p_layout, int32_t p_report, PidReport &r_report);

// Create New Effect (feature): effect type = constant force; Byte Count left 0 (Linux).
bool encode_create_constant_effect(const PidLayout &p_layout, PidReport &r_report);
// Set Effect as Linux writes it for a constant force with replay.length 0 (infinite),
// trigger 0, delay 0: gain = logical max, Direction Enable = 1, direction element 0.
bool encode_set_effect(const PidLayout &p_layout, uint8_t p_block_index, uint16_t p_direction, PidReport &r_report);
bool encode_set_constant_force(const PidLayout &p_layout, uint8_t p_block_index, int16_t p_level, PidReport &r_report);
bool encode_effect_operation(const PidLayout &p_layout, uint8_t p_block_index, EffectOperation p_operation,
		uint8_t p_loop_count, PidReport &r_report);
bool encode_block_free(const PidLayout &p_layout, uint8_t p_block_index, PidReport &r_report);
// Array: the command's key; bitmask (Variable): bit key-1 set, the others clear (K-new).
bool encode_device_control(const PidLayout &p_layout, DeviceCommand p_command, PidReport &r_report);
bool encode_device_gain(const PidLayout &p_layout, uint16_t p_gain, PidReport &r_report);

// The field values the encoders write, for "send only what changed" comparisons.
int64_t direction_value(const PidLayout &p_layout, uint16_t p_direction);
int64_t magnitude_value(const PidLayout &p_layout, int16_t p_level);
int64_t infinite_duration_value(const PidLayout &p_layout);

enum class BlockLoadResult : uint8_t {
	SUCCESS,
	FULL,
	ERROR,
	GARBAGE, // Wrong ID, truncated, unknown status, or a block index out of range.
};
const char *block_load_result_name(BlockLoadResult p_result);

// p_reply as hid_get_feature_report returned it (byte 0 = report ID).
BlockLoadResult decode_block_load(const PidLayout &p_layout, std::span<const uint8_t> p_reply, uint8_t &r_block_index);

} // namespace haptics::pid
