#pragma once

// The Falcon's normal-mode packets with Novint's SDK firmware (docs/devices/falcon.md,
// "Normal-mode packets" [NIF FalconFirmwareNovintSDK.cpp]): the host sends one 16-byte command per I/O cycle and the
// device answers with one 16-byte reply. Both are framed '<' ... '>' and carry 4-bit nibbles
// offset by 0x41 ('A'), least significant nibble first:
//
//   command: 3C | motor 1 (4 nibbles) | motor 2 | motor 3 | 41+flags | 41 | 3E
//   reply:   3C | encoder 1 (4 nibbles) | encoder 2 | encoder 3 | 41+(homed<<4|buttons) | ? | 3E
//
// Flags per the firmware CODE, which disagrees with its header's comment (docs/devices/falcon.md): homing
// 0x01, green LED 0x02, blue 0x04, red 0x08. Encoders are signed 16-bit.
//
// Replies arrive through the FTDI bridge as a byte stream, two status bytes at the head of
// every 64-byte USB packet and frames split across packets at will; FalconStreamAssembler
// turns that stream back into frames (strip, reassemble, keep the tail, resynchronise on
// garbage). Nothing here allocates: it runs on the device's I/O thread.

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>

namespace haptics::falcon {

inline constexpr size_t FALCON_PACKET_SIZE = 16;
inline constexpr uint8_t FALCON_FRAME_START = 0x3C; // '<'
inline constexpr uint8_t FALCON_FRAME_END = 0x3E; // '>'
inline constexpr uint8_t FALCON_NIBBLE_BASE = 0x41; // 'A'

inline constexpr uint8_t FALCON_FLAG_HOMING = 0x01;
inline constexpr uint8_t FALCON_LED_GREEN = 0x02;
inline constexpr uint8_t FALCON_LED_BLUE = 0x04;
inline constexpr uint8_t FALCON_LED_RED = 0x08;

inline constexpr uint8_t FALCON_HOMED_ALL = 0x07; // Bit i: motor i+1 homed.

// Grip buttons (FalconGripFourButton.h; docs/devices/falcon.md, "Normal-mode packets").
inline constexpr uint8_t FALCON_BUTTON_1_PLUS = 0x1;
inline constexpr uint8_t FALCON_BUTTON_2_FORWARD = 0x2;
inline constexpr uint8_t FALCON_BUTTON_3_CENTER = 0x4;
inline constexpr uint8_t FALCON_BUTTON_4_MINUS = 0x8;

using FalconPacket = uint8_t[FALCON_PACKET_SIZE];

struct FalconCommand {
	int16_t torque[3] = {}; // Motor words, already clamped (falcon_kinematics.h).
	uint8_t flags = 0; // FALCON_FLAG_HOMING | FALCON_LED_*; only the low nibble is sent.
};

struct FalconReply {
	int16_t encoder[3] = {};
	uint8_t homed = 0; // Bits 0-2.
	uint8_t buttons = 0; // FALCON_BUTTON_*.
	uint8_t byte14 = FALCON_NIBBLE_BASE; // Meaning unknown (docs/devices/falcon.md); kept for diagnostics.

	bool all_homed() const { return (homed & FALCON_HOMED_ALL) == FALCON_HOMED_ALL; }
};

void encode_falcon_command(const FalconCommand &p_command, FalconPacket &r_packet);
// The device side, for the scripted Falcon: errors name the offending byte.
Status decode_falcon_command(const uint8_t *p_bytes, size_t p_length, FalconCommand &r_command);

// Errors (naming the byte) for a wrong length, missing '<'/'>', a nibble byte outside
// 0x41..0x50 or a status byte outside 0x41..0xC0. Stricter than NIF, which masks any byte to
// its low nibble: checking the range is what lets the assembler tell a frame from garbage
// that happens to hold '<' and '>' fifteen bytes apart.
Status decode_falcon_reply(const uint8_t *p_bytes, size_t p_length, FalconReply &r_reply);
void encode_falcon_reply(const FalconReply &p_reply, FalconPacket &r_packet);

class FalconStreamAssembler {
public:
	// NIF's stream buffer size: two frames plus a partial one fit comfortably.
	static constexpr size_t CAPACITY = 128;

	struct Counters {
		uint64_t frames = 0; // Valid frames returned.
		uint64_t dropped_bytes = 0; // Garbage skipped while looking for '<', and overflow.
		uint64_t malformed_frames = 0; // A '<' whose 16 bytes were not a valid frame.
		uint64_t short_transfers = 0; // IN transfers too short to hold the status bytes.
	};

	// One bulk-IN transfer, as read: two status bytes per 64-byte packet are stripped.
	void push_transfer(const uint8_t *p_transfer, size_t p_length);
	// Payload bytes without status bytes. If they do not fit, the oldest bytes are dropped:
	// the newest data is what the I/O loop wants.
	void push_payload(const uint8_t *p_bytes, size_t p_length);
	// The next valid frame in the stream; false when no complete one is buffered (the tail
	// from the last '<' is kept for the next push).
	bool pop_reply(FalconReply &r_reply);
	void clear();

	size_t buffered() const { return size_; }
	const Counters &counters() const { return counters_; }

private:
	void drop_front(size_t p_count);

	uint8_t buffer_[CAPACITY] = {};
	size_t size_ = 0;
	Counters counters_;
};

} // namespace haptics::falcon
