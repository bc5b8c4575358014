#pragma once

// The CRC-32 the DualSense appends to every Bluetooth report (docs/devices/dualsense.md,
// "Bluetooth output report 0x31"; PS-K
// ps_check_crc32, SDL, DSC crc32.h): the standard reflected CRC-32 (polynomial 0xEDB88320,
// initial value 0xFFFFFFFF, final inversion, i.e. zlib's crc32) computed over ONE seed byte
// that names the report's direction, then the report bytes without the CRC itself. The seed
// is why a plain zlib CRC of the report never matches: a test that only compared against our
// own function would not catch a missing seed, so the tests pin golden values from zlib.
//
// Our own table-driven implementation (no zlib dependency in the core); the table is built at
// compile time.

#include <cstddef>
#include <cstdint>

namespace haptics::dualsense {

inline constexpr uint8_t CRC_SEED_INPUT = 0xA1; // Pad -> host input reports (PS-K).
inline constexpr uint8_t CRC_SEED_OUTPUT = 0xA2; // Host -> pad output reports (PS-K, SDL).
// Feature reports (PS-K; DSC defines 0x53 instead: docs/devices/sources.md notes the
// conflict). Only used to
// check the firmware-info report on Bluetooth, where a mismatch is harmless (unknown version).
inline constexpr uint8_t CRC_SEED_FEATURE = 0xA3;

// zlib-compatible CRC-32 of p_size bytes (crc32("123456789") = 0xCBF43926).
uint32_t crc32(const uint8_t *p_data, size_t p_size);
// CRC-32 over the seed byte followed by p_size bytes of p_data.
uint32_t crc32_seeded(uint8_t p_seed, const uint8_t *p_data, size_t p_size);

inline uint32_t read_le32(const uint8_t *p_bytes) {
	return static_cast<uint32_t>(p_bytes[0]) | static_cast<uint32_t>(p_bytes[1]) << 8 |
			static_cast<uint32_t>(p_bytes[2]) << 16 | static_cast<uint32_t>(p_bytes[3]) << 24;
}

inline void write_le32(uint8_t *r_bytes, uint32_t p_value) {
	r_bytes[0] = static_cast<uint8_t>(p_value);
	r_bytes[1] = static_cast<uint8_t>(p_value >> 8);
	r_bytes[2] = static_cast<uint8_t>(p_value >> 16);
	r_bytes[3] = static_cast<uint8_t>(p_value >> 24);
}

// True when the last 4 bytes of p_report (little-endian) are the seeded CRC of the bytes
// before them. False for reports shorter than 5 bytes.
bool crc_trailer_ok(uint8_t p_seed, const uint8_t *p_report, size_t p_size);

} // namespace haptics::dualsense
