#pragma once

// Kernel bitmaps in their two spellings: the bytes EVIOCGBIT copies (little-endian longs,
// read with test_bit() of evdev_abi.h) and sysfs's capabilities/* text, which the kernel
// prints as "%lx" longs separated by spaces, MOST significant first, with leading zero
// words left out (input_print_bitmap): "30000 0" on a 64-bit kernel is bit 80 = 0x50
// (FF_RUMBLE) and bit 81. The text is parsed into the EVIOCGBIT byte form so one
// test_bit() serves both.

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace haptics::evdev {

// The kernel's long, which sets the sysfs word width (userland and kernel agree on LP64).
inline constexpr uint32_t KERNEL_LONG_BITS = static_cast<uint32_t>(sizeof(long) * 8);

// Clears r_bits[0, p_size) then sets the bits p_text holds; bits beyond p_size * 8 are
// ignored. p_word_bits is 32 or 64. Errors (INVALID_ARGUMENT, message names p_what): a
// non-hex character, a word wider than p_word_bits, more than 64 words.
Status parse_sysfs_bitmask(std::string_view p_text, uint32_t p_word_bits, const char *p_what, uint8_t *r_bits,
		size_t p_size);

} // namespace haptics::evdev
