#pragma once

// Adaptive-trigger effect blocks: 11 bytes (mode + parameters p0..p9) that go at common
// offset 10 (right trigger, R2) or 21 (left trigger, L2) of the output report
// (docs/devices/dualsense.md, "USB output report 0x02"),
// with valid_flag0 bit 2 (right) or bit 3 (left) set so the pad applies them.
//
// Modes and packing from docs/devices/dualsense.md, "Adaptive-trigger blocks" (DSC's
// trigger_bitpacking_array, SDL testcontroller.c):
// the trigger's travel is 10 zones, 0 (released) .. 9 (fully pulled).
//  - off 0x05: all parameters zero; the trigger moves freely.
//  - feedback 0x21: p0..p1 = 10-bit active-zone mask (LE); p2..p5 = 30-bit field (LE), 3 bits
//    per zone holding strength-1 (strength 1..8). Resistance per zone.
//  - vibration 0x26: the same packing for amplitudes 1..8, p8 = frequency in Hz.
//  - weapon 0x25: p0..p1 = (1 << start) + (1 << end), start 2..7, end start+1..8; p2 =
//    strength-1. A resistance that "breaks" between start and end (a gun's trigger).
// Builders validate their parameters and return a Status naming the offending one; the
// block is untouched on error.

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>

namespace haptics::dualsense {

inline constexpr size_t TRIGGER_BLOCK_SIZE = 11;
inline constexpr int TRIGGER_ZONES = 10;
inline constexpr int TRIGGER_MAX_STRENGTH = 8;

inline constexpr uint8_t TRIGGER_MODE_OFF = 0x05;
inline constexpr uint8_t TRIGGER_MODE_FEEDBACK = 0x21;
inline constexpr uint8_t TRIGGER_MODE_WEAPON = 0x25;
inline constexpr uint8_t TRIGGER_MODE_VIBRATION = 0x26;

// Parameter index of the vibration frequency (p8 -> byte 9 of the block).
inline constexpr size_t TRIGGER_VIBRATION_FREQUENCY_PARAM = 8;

struct TriggerEffect {
	uint8_t bytes[TRIGGER_BLOCK_SIZE] = { TRIGGER_MODE_OFF };

	uint8_t mode() const { return bytes[0]; }
	uint8_t param(size_t p_index) const { return bytes[1 + p_index]; }
	bool operator==(const TriggerEffect &p_other) const;
};

TriggerEffect trigger_off();

// Per-zone form: p_strengths[z] in 0..8, 0 = zone inactive. At least one zone active.
Status trigger_feedback_zones(const uint8_t (&p_strengths)[TRIGGER_ZONES], TriggerEffect &r_effect);
// Resistance S (1..8) from zone p_start_zone (0..9) to the end of the travel.
Status trigger_feedback(int p_start_zone, int p_strength, TriggerEffect &r_effect);
// Per-zone amplitudes (0..8, 0 = inactive) vibrating at p_frequency_hz (1..255).
Status trigger_vibration_zones(const uint8_t (&p_amplitudes)[TRIGGER_ZONES], int p_frequency_hz, TriggerEffect &r_effect);
Status trigger_vibration(int p_start_zone, int p_amplitude, int p_frequency_hz, TriggerEffect &r_effect);
Status trigger_weapon(int p_start_zone, int p_end_zone, int p_strength, TriggerEffect &r_effect);

// Inverse of the feedback/vibration packing: the per-zone values (0 = inactive). False, with
// r_values zeroed, for blocks of another mode. Used by the property tests and by the
// scripted pad to report what a trigger would feel.
bool unpack_trigger_zones(const TriggerEffect &p_effect, uint8_t (&r_values)[TRIGGER_ZONES]);

// The largest zone strength of a feedback block, 0 for any other mode (off included).
int trigger_feedback_strength(const TriggerEffect &p_effect);

} // namespace haptics::dualsense
