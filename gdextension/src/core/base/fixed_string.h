#pragma once

// Text of at most N bytes held in place: what a realtime value (one that crosses threads
// through a seqlock, so stays trivially copyable) holds instead of a std::string. Always
// NUL-terminated; longer text is cut at N bytes (at a UTF-8 boundary) by assign(); code that
// writes it in place (snprintf into its data, N + 1 bytes) keeps to ASCII.

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace haptics {

template <size_t N>
struct FixedString {
	static constexpr size_t CAPACITY = N;

	char data[N + 1] = {};

	FixedString() = default;
	FixedString(std::string_view p_text) { assign(p_text); } // NOLINT: converts like a string.

	void assign(std::string_view p_text) {
		size_t size = p_text.size() < N ? p_text.size() : N;
		// Never end inside a UTF-8 sequence: back up over continuation bytes.
		while (size > 0 && size < p_text.size() && (static_cast<unsigned char>(p_text[size]) & 0xC0) == 0x80) {
			--size;
		}
		std::memcpy(data, p_text.data(), size);
		data[size] = '\0';
	}
	size_t size() const { return std::strlen(data); }
	bool empty() const { return data[0] == '\0'; }
	const char *c_str() const { return data; }
	std::string_view view() const { return { data, size() }; }
	std::string str() const { return std::string(view()); }
	bool operator==(const FixedString &p_other) const { return view() == p_other.view(); }
	// Reads and writes like the char array it replaces (snprintf into it; %s it).
	operator const char *() const { return data; } // NOLINT
	operator char *() { return data; } // NOLINT
};

} // namespace haptics
