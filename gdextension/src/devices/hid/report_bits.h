#pragma once

// Reading and writing values inside a HID report buffer. HID packs values little-endian and
// LSB-first across byte boundaries (HID 1.11 §5.8), at the bit offsets the descriptor parser
// computed. Everything is bounds-checked against the buffer: a truncated or garbled report
// is an error, never an out-of-bounds access. The bool forms are for the I/O thread (no
// Status to build); the Status forms name what failed.

#include "core/base/status.h"
#include "devices/hid/report_descriptor.h"

#include <cstdint>
#include <span>

namespace haptics::hid {

// p_bit_size in 1..32. False when the bits do not lie inside p_buffer.
bool extract_bits(std::span<const uint8_t> p_buffer, uint32_t p_bit_offset, uint32_t p_bit_size, uint32_t &r_value);
// Writes the low p_bit_size bits of p_value; the neighbouring bits are kept.
bool insert_bits(std::span<uint8_t> p_buffer, uint32_t p_bit_offset, uint32_t p_bit_size, uint32_t p_value);
int64_t sign_extend(uint32_t p_value, uint32_t p_bit_size);

// Whether p_value is representable in the field's bits (two's complement when the field's
// logical minimum is negative, else unsigned). The logical range is NOT enforced: drivers
// write out-of-range values on purpose (Linux writes trigger button 0 into a 1..8 field).
bool field_fits(const Field &p_field, int64_t p_value);

// Value p_index (0-based) of p_field; signed when the field's logical minimum is negative.
bool read_field_value(std::span<const uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t &r_value);
bool write_field_value(std::span<uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t p_value);

Status read_field(std::span<const uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t &r_value);
Status write_field(std::span<uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t p_value);

} // namespace haptics::hid
