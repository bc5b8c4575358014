#pragma once

// Shared by the evdev tests: expected bytes built independently of the encoder under test
// (field by field from docs/devices/evdev.md's offsets), filters over the scripted kernel's record, and
// a bounded wait for the device's I/O thread.

#include "dev_tools/evdev/scripted_evdev_kernel.h"

#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

namespace haptics::evdev_test {

using namespace haptics::evdev;

// struct ff_effect for FF_CONSTANT: type 0x52 @0, id @2, direction @4, replay.length @10,
// level @16; everything else zero (docs/devices/evdev.md).
inline std::vector<uint8_t> expected_constant_effect(int16_t p_id, uint16_t p_direction, int16_t p_level,
		uint16_t p_length_ms = CONSTANT_EFFECT_LENGTH_MS) {
	std::vector<uint8_t> bytes(48, 0);
	bytes[0] = 0x52;
	bytes[2] = static_cast<uint8_t>(static_cast<uint16_t>(p_id) & 0xff);
	bytes[3] = static_cast<uint8_t>(static_cast<uint16_t>(p_id) >> 8);
	bytes[4] = static_cast<uint8_t>(p_direction & 0xff);
	bytes[5] = static_cast<uint8_t>(p_direction >> 8);
	bytes[10] = static_cast<uint8_t>(p_length_ms & 0xff);
	bytes[11] = static_cast<uint8_t>(p_length_ms >> 8);
	bytes[16] = static_cast<uint8_t>(static_cast<uint16_t>(p_level) & 0xff);
	bytes[17] = static_cast<uint8_t>(static_cast<uint16_t>(p_level) >> 8);
	return bytes;
}

// struct input_event: 16 bytes of zero time, type @16, code @18, value @20.
inline std::vector<uint8_t> expected_event(uint16_t p_type, uint16_t p_code, int32_t p_value) {
	std::vector<uint8_t> bytes(24, 0);
	bytes[16] = static_cast<uint8_t>(p_type & 0xff);
	bytes[17] = static_cast<uint8_t>(p_type >> 8);
	bytes[18] = static_cast<uint8_t>(p_code & 0xff);
	bytes[19] = static_cast<uint8_t>(p_code >> 8);
	const uint32_t value = static_cast<uint32_t>(p_value);
	for (int i = 0; i < 4; ++i) {
		bytes[20 + i] = static_cast<uint8_t>((value >> (8 * i)) & 0xff);
	}
	return bytes;
}

// The calls that change the device: ioctls that are not queries (EVIOCSFF, EVIOCRMFF) and
// writes. Reads and the EVIOCG* queries are left out.
inline std::vector<ScriptedEvdevCall> ff_calls(const std::vector<ScriptedEvdevCall> &p_calls) {
	std::vector<ScriptedEvdevCall> result;
	for (const ScriptedEvdevCall &call : p_calls) {
		const bool ff_ioctl = call.kind == ScriptedEvdevCall::Kind::IOCTL &&
				(call.request == EVDEV_EVIOCSFF || call.request == EVDEV_EVIOCRMFF);
		if (ff_ioctl || call.kind == ScriptedEvdevCall::Kind::WRITE) {
			result.push_back(call);
		}
	}
	return result;
}

inline std::vector<uint8_t> int_bytes(int32_t p_value) {
	const uint32_t value = static_cast<uint32_t>(p_value);
	return { static_cast<uint8_t>(value & 0xff), static_cast<uint8_t>((value >> 8) & 0xff),
		static_cast<uint8_t>((value >> 16) & 0xff), static_cast<uint8_t>(value >> 24) };
}

// Polls p_condition every millisecond for at most p_timeout_s; true once it held.
template <typename Condition>
bool wait_until(Condition p_condition, double p_timeout_s = 2.0) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_timeout_s);
	while (std::chrono::steady_clock::now() < deadline) {
		if (p_condition()) {
			return true;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	return p_condition();
}

} // namespace haptics::evdev_test
