#pragma once

// The bytes of the wire format (docs/values.md): little-endian integers and IEEE floats, a
// string as a u16 byte count and UTF-8, an array as a u32 count and its items, an optional
// as a 0/1 byte. WireWriter appends; WireReader reads with every bound checked, and its
// first failure sticks, naming the field by its path ("HapticFrame.contacts[2].normal").
// Game thread only: both may allocate.

#include "core/base/coordinates.h"
#include "core/base/status.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace haptics {

class WireWriter {
public:
	void u8(uint8_t p_value) { bytes_.push_back(p_value); }
	void u16(uint16_t p_value) { put(p_value, 2); }
	void u32(uint32_t p_value) { put(p_value, 4); }
	void u64(uint64_t p_value) { put(p_value, 8); }
	void f32(float p_value);
	void f64(double p_value);
	void text(const std::string &p_value);

	const std::vector<uint8_t> &bytes() const { return bytes_; }
	std::vector<uint8_t> take() { return std::move(bytes_); }

	// How game vectors are written: as a 2D game's or a 3D game's (coordinates.h).
	GameSpace space = GameSpace::PLANE;

private:
	void put(uint64_t p_value, int p_size);

	std::vector<uint8_t> bytes_;
};

class WireReader {
public:
	// p_what names the value in messages (its GDScript class, e.g. "HapticFrame").
	WireReader(std::span<const uint8_t> p_bytes, const char *p_what);

	bool ok() const { return status_.ok(); }
	const Status &status() const { return status_; }
	// The status once every byte was read: trailing bytes are an error too.
	Status finish();

	// Each returns 0 (and fails) past the end; once failed, every read returns 0.
	uint8_t u8();
	uint16_t u16() { return static_cast<uint16_t>(get(2)); }
	uint32_t u32() { return static_cast<uint32_t>(get(4)); }
	uint64_t u64() { return get(8); }
	float f32();
	double f64();
	// At most p_max_bytes of valid UTF-8.
	std::string text(uint32_t p_max_bytes);

	// The path the messages name: entered for a field, an item, a nested value.
	void enter(const char *p_name);
	void enter_item(size_t p_index);
	void leave();
	// How game vectors are read: as a 2D game's or a 3D game's (coordinates.h).
	GameSpace space = GameSpace::PLANE;

	// Fails with p_code and "<path>: <message>" unless already failed.
	void fail(StatusCode p_code, const char *p_format, ...) __attribute__((format(HAPTICS_PRINTF, 3, 4)));

private:
	uint64_t get(int p_size);
	bool need(size_t p_size);

	std::span<const uint8_t> bytes_;
	size_t offset_ = 0;
	Status status_;
	std::string path_;
	std::vector<size_t> marks_;
};

} // namespace haptics
