#include "devices/dualsense/dualsense_crc.h"

#include <array>

namespace haptics::dualsense {

namespace {

constexpr uint32_t POLYNOMIAL = 0xEDB88320u; // Reflected 0x04C11DB7.

constexpr std::array<uint32_t, 256> make_table() {
	std::array<uint32_t, 256> table{};
	for (uint32_t byte = 0; byte < 256; ++byte) {
		uint32_t value = byte;
		for (int bit = 0; bit < 8; ++bit) {
			value = (value & 1u) ? (value >> 1) ^ POLYNOMIAL : value >> 1;
		}
		table[byte] = value;
	}
	return table;
}

constexpr std::array<uint32_t, 256> TABLE = make_table();

// Register form: start at 0xFFFFFFFF, invert at the end.
uint32_t update(uint32_t p_register, const uint8_t *p_data, size_t p_size) {
	for (size_t i = 0; i < p_size; ++i) {
		p_register = TABLE[(p_register ^ p_data[i]) & 0xFFu] ^ (p_register >> 8);
	}
	return p_register;
}

} // namespace

uint32_t crc32(const uint8_t *p_data, size_t p_size) {
	return ~update(0xFFFFFFFFu, p_data, p_size);
}

uint32_t crc32_seeded(uint8_t p_seed, const uint8_t *p_data, size_t p_size) {
	return ~update(update(0xFFFFFFFFu, &p_seed, 1), p_data, p_size);
}

bool crc_trailer_ok(uint8_t p_seed, const uint8_t *p_report, size_t p_size) {
	if (p_report == nullptr || p_size < 5) {
		return false;
	}
	return crc32_seeded(p_seed, p_report, p_size - 4) == read_le32(p_report + p_size - 4);
}

} // namespace haptics::dualsense
