#pragma once

// Shared by the dualsense tests: whole-buffer comparisons that print the first differing byte.

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace haptics::dualsense::test {

// "" when equal, else where and how they differ (so a failing CHECK says which byte).
inline std::string byte_difference(const uint8_t *p_actual, size_t p_actual_size, const uint8_t *p_expected,
		size_t p_expected_size) {
	char text[96];
	if (p_actual_size != p_expected_size) {
		std::snprintf(text, sizeof(text), "size %zu, expected %zu", p_actual_size, p_expected_size);
		return text;
	}
	for (size_t i = 0; i < p_actual_size; ++i) {
		if (p_actual[i] != p_expected[i]) {
			std::snprintf(text, sizeof(text), "byte %zu is 0x%02X, expected 0x%02X", i, p_actual[i], p_expected[i]);
			return text;
		}
	}
	return "";
}

} // namespace haptics::dualsense::test

#define CHECK_BYTES(p_actual, p_actual_size, p_expected, p_expected_size) \
	CHECK(::haptics::dualsense::test::byte_difference((p_actual), (p_actual_size), (p_expected), (p_expected_size)) == "")
