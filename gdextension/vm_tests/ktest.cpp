#include "ktest.h"

#include <cstdio>

namespace haptics::vm {

bool Report::check(bool p_ok, const std::string &p_what) {
	std::printf("KTEST %s %s %s\n", scenario_.c_str(), p_ok ? "PASS" : "FAIL", p_what.c_str());
	std::fflush(stdout);
	(p_ok ? passed_ : failed_)++;
	return p_ok;
}

void Report::wire(const std::string &p_what, std::span<const uint8_t> p_bytes) {
	std::printf("KWIRE %s %s: %s\n", scenario_.c_str(), p_what.c_str(), hex(p_bytes).c_str());
	std::fflush(stdout);
}

void Report::info(const std::string &p_what) {
	std::printf("KINFO %s %s\n", scenario_.c_str(), p_what.c_str());
	std::fflush(stdout);
}

std::string hex(std::span<const uint8_t> p_bytes) {
	std::string text;
	char byte[4];
	for (const uint8_t value : p_bytes) {
		std::snprintf(byte, sizeof(byte), text.empty() ? "%02x" : " %02x", value);
		text += byte;
	}
	return text;
}

} // namespace haptics::vm
