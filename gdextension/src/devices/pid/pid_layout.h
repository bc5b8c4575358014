#pragma once

// Where the PID reports and fields a constant-force effect needs live in one device's
// report descriptor, found by usage with the Linux hid-pidff rules (docs/devices/hid-pid.md,
// "How the kernel finds reports and fields"), so any
// conforming firmware works without a hard-coded byte layout:
//  - a report is classified by its first field's Logical-collection usage, else by the
//    parent Logical collection's; Output reports first, then Feature (which win);
//  - "special" array fields by their collection usage (effect type 0x25, direction 0x57,
//    device control 0x96, block load status 0x8B, effect operation 0x78), the selector
//    arrays with logical minimum 1; their keys are 1-based positions in the usage list;
//  - value fields only in fields whose usage count equals the report count (Linux maxusage).
// Device-specific behaviour the descriptor reveals is recorded as quirks: Start Delay
// missing (K-new MISSING_DELAY), Device Control as a bitmask (Variable) rather than an array,
// a device-control field without logical minimum 1 (K-new PERMISSIVE_CONTROL), selector
// arrays whose logical range a Windows rebuild of the descriptor gave as "maximum..0".

#include "core/base/status.h"
#include "devices/hid/report_descriptor.h"

#include <cstdint>
#include <span>

namespace haptics::pid {

// One value inside a report: field index into the descriptor's fields, and element.
struct FieldRef {
	int32_t field = -1;
	uint32_t index = 0;
	bool found() const { return field >= 0; }
};

enum PidQuirk : uint32_t {
	QUIRK_MISSING_DELAY = 1u << 0, // Bit values as K-new hid-pidff.h.
	QUIRK_PERMISSIVE_CONTROL = 1u << 2,
	QUIRK_DEVICE_CONTROL_BITMASK = 1u << 16, // Ours: not a kernel quirk bit, a branch.
	QUIRK_AJ_FIRMWARE = 1u << 17, // Looks like AJ's descriptor (infinite = 0x7FFF).
	QUIRK_REVERSED_ARRAY_RANGES = 1u << 18, // Ours: selector arrays read back from N..0.
};

// What "infinite duration" is written as (docs/devices/hid-pid.md, "Infinite duration"). Linux writes all ones,
// (1 << size) - 1; AJ's firmware only treats its logical maximum 0x7FFF as infinite.
enum class InfiniteDuration : uint8_t {
	ALL_ONES = 0,
	LOGICAL_MAX = 1,
};

struct SetEffectLayout {
	int32_t report = -1; // Into descriptor.reports.
	FieldRef block_index, duration, gain, trigger_button, trigger_repeat, direction_enable, start_delay;
	int32_t type_field = -1; // Special 0x25.
	int32_t direction_field = -1; // Special 0x57; element 0 is written (as Linux).
	uint8_t constant_key = 0; // Array value selecting ET Constant Force.
};

struct SetConstantLayout {
	int32_t report = -1;
	FieldRef block_index, magnitude;
};

struct EffectOperationLayout {
	int32_t report = -1;
	FieldRef block_index, loop_count;
	int32_t operation_field = -1; // Special 0x78.
	uint8_t start_key = 0, start_solo_key = 0, stop_key = 0;
};

struct DeviceControlLayout {
	int32_t report = -1;
	int32_t field = -1; // Special 0x96.
	bool bitmask = false; // Variable: set bit key-1; else Array: write key.
	uint8_t enable_key = 0, disable_key = 0, stop_all_key = 0, reset_key = 0, pause_key = 0, continue_key = 0;
};

struct BlockLoadLayout {
	int32_t report = -1;
	FieldRef block_index, ram_pool_available;
	int32_t status_field = -1; // Special 0x8B.
	uint8_t success_key = 0, full_key = 0, error_key = 0;
};

struct PidLayout {
	hid::ReportDescriptor descriptor;
	SetEffectLayout set_effect;
	SetConstantLayout set_constant;
	EffectOperationLayout effect_operation;
	DeviceControlLayout device_control;
	BlockLoadLayout block_load;
	int32_t create_new_effect_report = -1;
	int32_t create_type_field = -1; // Special 0x25 in Create New Effect.
	uint8_t create_constant_key = 0;
	int32_t block_free_report = -1;
	FieldRef block_free_index;
	int32_t device_gain_report = -1;
	FieldRef device_gain;
	int32_t pool_report = -1; // Found but never read: AJ frees every effect on a Pool GET.
	uint32_t max_effects = 0; // Block Load EBI range, capped at 64 (PID_EFFECTS_MAX).
	uint32_t quirks = 0; // PidQuirk bits.
	InfiniteDuration infinite_duration = InfiniteDuration::ALL_ONES;

	// Finds everything above in p_descriptor (moved in). Fails naming the first missing
	// report or field, e.g. "PID layout: no Set Constant Force report (0x73)".
	static Status build(hid::ReportDescriptor &&p_descriptor, PidLayout &r_layout);

	const hid::Report &report(int32_t p_index) const { return descriptor.reports[static_cast<size_t>(p_index)]; }
	const hid::Field &field(int32_t p_index) const { return descriptor.fields[static_cast<size_t>(p_index)]; }
	const hid::Field &field(const FieldRef &p_ref) const { return field(p_ref.field); }
};

// Whether every field p_layout writes or reads can hold its logical range in its bits
// (Report Size 8 with Logical Maximum 1000 cannot, nor -10000..10000 in 8 signed bits).
// PidLayout::build runs it, so such a descriptor is refused at probe and open, naming the
// report and usage, e.g. "PID layout: Set Effect report 1: Gain (0x52) has logical range
// 0..1000, which 8 unsigned bits cannot hold (descriptor byte 240)".
Status check_field_ranges(const PidLayout &p_layout);

// Reads the selector arrays (0x25, 0x78, 0x8B, 0x96) a descriptor rebuilt on Windows gives as
// N..0 as the 1..N they were (docs/devices/hid.md, "Windows: the descriptor rebuilt from parsed
// data"); returns how many. PidLayout::build runs it first; other reversed ranges stay refused.
uint32_t restore_reversed_selector_arrays(hid::ReportDescriptor &r_descriptor);

inline constexpr uint32_t PID_EFFECTS_MAX = 64; // K-old/K-new PID_EFFECTS_MAX.
inline constexpr uint32_t PID_MAX_REPORT_BYTES = 64; // Our fixed buffers: a full-speed packet.

// Whether p_descriptor holds a usable PID layout (for probing a device whose top-level
// collection is a joystick, as AJ's is); p_reason says what is missing.
bool has_pid_layout(std::span<const uint8_t> p_descriptor_bytes, Status *r_reason = nullptr);

} // namespace haptics::pid
