#include "devices/evdev/evdev_bits.h"

#include "devices/evdev/evdev_abi.h"

#include <cstring>

namespace haptics::evdev {

namespace {

constexpr size_t MAX_WORDS = 64; // KEY_CNT is 12 longs; anything near 64 is garbage.

bool is_space(char p_char) {
	return p_char == ' ' || p_char == '\n' || p_char == '\t' || p_char == '\r';
}

int hex_value(char p_char) {
	if (p_char >= '0' && p_char <= '9') {
		return p_char - '0';
	}
	if (p_char >= 'a' && p_char <= 'f') {
		return p_char - 'a' + 10;
	}
	if (p_char >= 'A' && p_char <= 'F') {
		return p_char - 'A' + 10;
	}
	return -1;
}

} // namespace

Status parse_sysfs_bitmask(std::string_view p_text, uint32_t p_word_bits, const char *p_what, uint8_t *r_bits,
		size_t p_size) {
	std::memset(r_bits, 0, p_size);
	if (p_word_bits != 32 && p_word_bits != 64) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: word width must be 32 or 64 bits (got %u)", p_what,
				p_word_bits);
	}
	// Words are written most significant first, so count them before placing any.
	std::string_view words[MAX_WORDS];
	size_t count = 0;
	size_t i = 0;
	while (i < p_text.size()) {
		if (is_space(p_text[i])) {
			++i;
			continue;
		}
		size_t end = i;
		while (end < p_text.size() && !is_space(p_text[end])) {
			++end;
		}
		if (count == MAX_WORDS) {
			return Status::error(StatusCode::INVALID_ARGUMENT, "%s: more than %zu words", p_what, MAX_WORDS);
		}
		words[count++] = p_text.substr(i, end - i);
		i = end;
	}
	const size_t max_digits = p_word_bits / 4;
	for (size_t w = 0; w < count; ++w) {
		const std::string_view word = words[w];
		// Leading zeros do not widen a word ("%lx" never writes them, but be lenient).
		size_t first = 0;
		while (first + 1 < word.size() && word[first] == '0') {
			++first;
		}
		if (word.size() - first > max_digits) {
			return Status::error(StatusCode::INVALID_ARGUMENT, "%s: word '%.*s' is wider than %u bits", p_what,
					static_cast<int>(word.size() > 40 ? 40 : word.size()), word.data(), p_word_bits);
		}
		const uint32_t base_bit = static_cast<uint32_t>((count - 1 - w) * p_word_bits);
		for (size_t d = 0; d < word.size(); ++d) {
			const int value = hex_value(word[d]);
			if (value < 0) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s: '%c' in '%.*s' is not a hex digit", p_what,
						word[d] >= 0x20 && word[d] < 0x7f ? word[d] : '?',
						static_cast<int>(word.size() > 40 ? 40 : word.size()), word.data());
			}
			const uint32_t nibble_bit = base_bit + static_cast<uint32_t>((word.size() - 1 - d) * 4);
			for (uint32_t b = 0; b < 4; ++b) {
				if ((value >> b) & 1) {
					set_bit(r_bits, p_size, nibble_bit + b);
				}
			}
		}
	}
	return Status::success();
}

} // namespace haptics::evdev
