#include "devices/falcon/falcon_codec.h"

#include "devices/falcon/falcon_ftdi.h"

#include <cstring>

namespace haptics::falcon {

namespace {

constexpr uint8_t NIBBLE_MAX_BYTE = FALCON_NIBBLE_BASE + 0x0F; // 0x50
constexpr uint8_t STATUS_MAX_BYTE = FALCON_NIBBLE_BASE + 0x7F; // 0xC0: 3 homing + 4 button bits.

// 16 bits as four nibbles + 0x41, least significant first.
void put_word(uint16_t p_word, uint8_t *r_bytes) {
	for (int k = 0; k < 4; ++k) {
		r_bytes[k] = static_cast<uint8_t>(FALCON_NIBBLE_BASE + ((p_word >> (4 * k)) & 0x0F));
	}
}

int16_t get_word(const uint8_t *p_bytes) {
	uint16_t word = 0;
	for (int k = 0; k < 4; ++k) {
		word = static_cast<uint16_t>(word | (((p_bytes[k] - FALCON_NIBBLE_BASE) & 0x0F) << (4 * k)));
	}
	return static_cast<int16_t>(word); // Two's complement: 0xFA59 -> -1447.
}

Status check_frame(const char *p_what, const uint8_t *p_bytes, size_t p_length) {
	if (p_bytes == nullptr || p_length != FALCON_PACKET_SIZE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon %s: %zu bytes, expected 16", p_what,
				p_bytes ? p_length : 0);
	}
	if (p_bytes[0] != FALCON_FRAME_START || p_bytes[15] != FALCON_FRAME_END) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon %s: not framed '<'...'>' (byte 0 = 0x%02X, byte 15 = 0x%02X)",
				p_what, p_bytes[0], p_bytes[15]);
	}
	for (size_t i = 1; i <= 12; ++i) {
		if (p_bytes[i] < FALCON_NIBBLE_BASE || p_bytes[i] > NIBBLE_MAX_BYTE) {
			return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon %s: byte %zu is 0x%02X, not a nibble + 0x41", p_what, i,
					p_bytes[i]);
		}
	}
	return Status::success();
}

} // namespace

void encode_falcon_command(const FalconCommand &p_command, FalconPacket &r_packet) {
	r_packet[0] = FALCON_FRAME_START;
	for (int motor = 0; motor < 3; ++motor) {
		put_word(static_cast<uint16_t>(p_command.torque[motor]), &r_packet[1 + 4 * motor]);
	}
	r_packet[13] = static_cast<uint8_t>(FALCON_NIBBLE_BASE + (p_command.flags & 0x0F));
	r_packet[14] = FALCON_NIBBLE_BASE; // NIF's unused "k" field, always 0.
	r_packet[15] = FALCON_FRAME_END;
}

Status decode_falcon_command(const uint8_t *p_bytes, size_t p_length, FalconCommand &r_command) {
	const Status framed = check_frame("command", p_bytes, p_length);
	if (!framed) {
		return framed;
	}
	if (p_bytes[13] < FALCON_NIBBLE_BASE || p_bytes[13] > NIBBLE_MAX_BYTE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon command: byte 13 (flags) is 0x%02X, not a nibble + 0x41",
				p_bytes[13]);
	}
	FalconCommand command;
	for (int motor = 0; motor < 3; ++motor) {
		command.torque[motor] = get_word(&p_bytes[1 + 4 * motor]);
	}
	command.flags = static_cast<uint8_t>(p_bytes[13] - FALCON_NIBBLE_BASE);
	r_command = command;
	return Status::success();
}

Status decode_falcon_reply(const uint8_t *p_bytes, size_t p_length, FalconReply &r_reply) {
	const Status framed = check_frame("reply", p_bytes, p_length);
	if (!framed) {
		return framed;
	}
	if (p_bytes[13] < FALCON_NIBBLE_BASE || p_bytes[13] > STATUS_MAX_BYTE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "Falcon reply: byte 13 (status) is 0x%02X, outside 0x41..0xC0",
				p_bytes[13]);
	}
	FalconReply reply;
	for (int motor = 0; motor < 3; ++motor) {
		reply.encoder[motor] = get_word(&p_bytes[1 + 4 * motor]);
	}
	const uint8_t status = static_cast<uint8_t>(p_bytes[13] - FALCON_NIBBLE_BASE);
	reply.homed = static_cast<uint8_t>((status >> 4) & FALCON_HOMED_ALL);
	reply.buttons = static_cast<uint8_t>(status & 0x0F);
	reply.byte14 = p_bytes[14];
	r_reply = reply;
	return Status::success();
}

void encode_falcon_reply(const FalconReply &p_reply, FalconPacket &r_packet) {
	r_packet[0] = FALCON_FRAME_START;
	for (int motor = 0; motor < 3; ++motor) {
		put_word(static_cast<uint16_t>(p_reply.encoder[motor]), &r_packet[1 + 4 * motor]);
	}
	r_packet[13] = static_cast<uint8_t>(FALCON_NIBBLE_BASE + (((p_reply.homed & FALCON_HOMED_ALL) << 4) | (p_reply.buttons & 0x0F)));
	r_packet[14] = p_reply.byte14;
	r_packet[15] = FALCON_FRAME_END;
}

void FalconStreamAssembler::push_transfer(const uint8_t *p_transfer, size_t p_length) {
	if (p_transfer == nullptr || p_length == 0) {
		return;
	}
	// A transfer is one or more 64-byte packets; strip each one's status bytes in place of
	// copying the whole transfer first.
	for (size_t packet = 0; packet < p_length; packet += FTDI_PACKET_SIZE) {
		const size_t remaining = p_length - packet;
		const size_t length = remaining < FTDI_PACKET_SIZE ? remaining : FTDI_PACKET_SIZE;
		if (length < FTDI_STATUS_BYTES) {
			++counters_.short_transfers;
			continue;
		}
		push_payload(p_transfer + packet + FTDI_STATUS_BYTES, length - FTDI_STATUS_BYTES);
	}
}

void FalconStreamAssembler::push_payload(const uint8_t *p_bytes, size_t p_length) {
	if (p_bytes == nullptr) {
		return;
	}
	if (p_length > CAPACITY) {
		counters_.dropped_bytes += size_ + (p_length - CAPACITY);
		size_ = 0;
		p_bytes += p_length - CAPACITY;
		p_length = CAPACITY;
	}
	if (size_ + p_length > CAPACITY) {
		drop_front(size_ + p_length - CAPACITY);
	}
	std::memcpy(buffer_ + size_, p_bytes, p_length);
	size_ += p_length;
}

bool FalconStreamAssembler::pop_reply(FalconReply &r_reply) {
	while (size_ > 0) {
		size_t start = 0;
		while (start < size_ && buffer_[start] != FALCON_FRAME_START) {
			++start;
		}
		drop_front(start);
		if (size_ < FALCON_PACKET_SIZE) {
			return false; // Keep the partial frame (or nothing) for the next transfer.
		}
		if (decode_falcon_reply(buffer_, FALCON_PACKET_SIZE, r_reply)) {
			size_ -= FALCON_PACKET_SIZE;
			std::memmove(buffer_, buffer_ + FALCON_PACKET_SIZE, size_);
			++counters_.frames;
			return true;
		}
		// Not a frame: skip this '<' and look for the next one.
		++counters_.malformed_frames;
		drop_front(1);
	}
	return false;
}

void FalconStreamAssembler::clear() {
	size_ = 0;
	counters_ = Counters{};
}

void FalconStreamAssembler::drop_front(size_t p_count) {
	if (p_count == 0) {
		return;
	}
	counters_.dropped_bytes += p_count;
	size_ -= p_count;
	std::memmove(buffer_, buffer_ + p_count, size_);
}

} // namespace haptics::falcon
