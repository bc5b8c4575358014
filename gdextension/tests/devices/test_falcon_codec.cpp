// The Falcon's 16-byte packets (docs/devices/falcon.md) byte for byte, and the stream assembler
// that rebuilds reply frames from FTDI bulk-IN transfers (status bytes, split frames, tails,
// garbage), with a bounded fuzz loop that must stay clean under ASan/UBSan.

#include "devices/falcon/falcon_codec.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace haptics;
using namespace haptics::falcon;

namespace {

std::vector<uint8_t> bytes_of(const FalconPacket &p_packet) {
	return std::vector<uint8_t>(p_packet, p_packet + FALCON_PACKET_SIZE);
}

// docs/devices/falcon.md's golden reply: encoders (-1447, 0, 0), homing 7, buttons 5.
const std::vector<uint8_t> GOLDEN_REPLY = { 0x3C, 0x4A, 0x46, 0x4B, 0x50, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41,
	0xB6, 0x41, 0x3E };

std::vector<uint8_t> reply_bytes(int16_t p_e1, int16_t p_e2, int16_t p_e3, uint8_t p_homed = 0, uint8_t p_buttons = 0) {
	FalconReply reply;
	reply.encoder[0] = p_e1;
	reply.encoder[1] = p_e2;
	reply.encoder[2] = p_e3;
	reply.homed = p_homed;
	reply.buttons = p_buttons;
	FalconPacket packet;
	encode_falcon_reply(reply, packet);
	return bytes_of(packet);
}

// One bulk-IN transfer: FTDI status bytes, then the payload.
std::vector<uint8_t> transfer(const std::vector<uint8_t> &p_payload) {
	std::vector<uint8_t> out = { 0x31, 0x60 };
	out.insert(out.end(), p_payload.begin(), p_payload.end());
	return out;
}

} // namespace

TEST_CASE("falcon codec: golden command, zero torques, green LED, no homing") {
	FalconCommand command;
	command.flags = FALCON_LED_GREEN;
	FalconPacket packet;
	encode_falcon_command(command, packet);
	CHECK(bytes_of(packet) ==
			std::vector<uint8_t>{ 0x3C, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x43, 0x41, 0x3E });
}

TEST_CASE("falcon codec: golden command, torques (100, -100, 0), red LED + homing") {
	FalconCommand command;
	command.torque[0] = 100;
	command.torque[1] = -100;
	command.flags = FALCON_LED_RED | FALCON_FLAG_HOMING;
	FalconPacket packet;
	encode_falcon_command(command, packet);
	CHECK(bytes_of(packet) ==
			std::vector<uint8_t>{ 0x3C, 0x45, 0x47, 0x41, 0x41, 0x4D, 0x4A, 0x50, 0x50, 0x41, 0x41, 0x41, 0x41, 0x4A, 0x41, 0x3E });
	// And the device side reads back what was sent.
	FalconCommand decoded;
	REQUIRE(decode_falcon_command(packet, FALCON_PACKET_SIZE, decoded));
	CHECK(decoded.torque[0] == 100);
	CHECK(decoded.torque[1] == -100);
	CHECK(decoded.torque[2] == 0);
	CHECK(decoded.flags == (FALCON_LED_RED | FALCON_FLAG_HOMING));
}

TEST_CASE("falcon codec: LED and homing bits follow the firmware code, not its header comment") {
	// Code: homing 0x01, green 0x02, blue 0x04, red 0x08 (the header says red 0x02, homing 0x10).
	CHECK(FALCON_FLAG_HOMING == 0x01);
	CHECK(FALCON_LED_GREEN == 0x02);
	CHECK(FALCON_LED_BLUE == 0x04);
	CHECK(FALCON_LED_RED == 0x08);
	FalconCommand command;
	command.flags = FALCON_LED_BLUE;
	FalconPacket packet;
	encode_falcon_command(command, packet);
	CHECK(packet[13] == 0x45);
	CHECK(packet[14] == 0x41);
}

TEST_CASE("falcon codec: int16 extremes survive the nibble packing") {
	FalconCommand command;
	command.torque[0] = INT16_MIN;
	command.torque[1] = INT16_MAX;
	command.torque[2] = -1;
	FalconPacket packet;
	encode_falcon_command(command, packet);
	CHECK(bytes_of(packet) ==
			std::vector<uint8_t>{ 0x3C, 0x41, 0x41, 0x41, 0x49, 0x50, 0x50, 0x50, 0x48, 0x50, 0x50, 0x50, 0x50, 0x41, 0x41, 0x3E });
	FalconCommand decoded;
	REQUIRE(decode_falcon_command(packet, FALCON_PACKET_SIZE, decoded));
	CHECK(decoded.torque[0] == INT16_MIN);
	CHECK(decoded.torque[1] == INT16_MAX);
	CHECK(decoded.torque[2] == -1);
}

TEST_CASE("falcon codec: golden reply decodes to encoders (-1447, 0, 0), homing 7, buttons 5") {
	FalconReply reply;
	REQUIRE(decode_falcon_reply(GOLDEN_REPLY.data(), GOLDEN_REPLY.size(), reply));
	CHECK(reply.encoder[0] == -1447);
	CHECK(reply.encoder[1] == 0);
	CHECK(reply.encoder[2] == 0);
	CHECK(reply.homed == 7);
	CHECK(reply.all_homed());
	CHECK(reply.buttons == 5);
	CHECK(reply.buttons == (FALCON_BUTTON_1_PLUS | FALCON_BUTTON_3_CENTER));
	// The scripted firmware's encoder writes the same bytes.
	CHECK(reply_bytes(-1447, 0, 0, 7, 5) == GOLDEN_REPLY);
}

TEST_CASE("falcon codec: partial homing is not homed") {
	FalconReply reply;
	const std::vector<uint8_t> bytes = reply_bytes(10, 20, 30, 0x5, 0);
	REQUIRE(decode_falcon_reply(bytes.data(), bytes.size(), reply));
	CHECK(reply.homed == 0x5);
	CHECK_FALSE(reply.all_homed());
	CHECK(reply.encoder[2] == 30);
}

TEST_CASE("falcon codec: malformed replies are errors naming the byte") {
	FalconReply reply;
	std::vector<uint8_t> bytes = GOLDEN_REPLY;
	Status status = decode_falcon_reply(bytes.data(), 15, reply);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "15 bytes") != nullptr);

	CHECK(decode_falcon_reply(nullptr, 16, reply).code() == StatusCode::INVALID_ARGUMENT);

	bytes[15] = 0x3D;
	status = decode_falcon_reply(bytes.data(), bytes.size(), reply);
	CHECK(std::strstr(status.message(), "byte 15 = 0x3D") != nullptr);

	bytes = GOLDEN_REPLY;
	bytes[7] = 0x51; // One past the last nibble byte.
	status = decode_falcon_reply(bytes.data(), bytes.size(), reply);
	CHECK(std::strstr(status.message(), "byte 7 is 0x51") != nullptr);

	bytes = GOLDEN_REPLY;
	bytes[13] = 0xC1;
	status = decode_falcon_reply(bytes.data(), bytes.size(), reply);
	CHECK(std::strstr(status.message(), "byte 13") != nullptr);
	// A failed decode leaves the output alone.
	CHECK(reply.encoder[0] == 0);
}

TEST_CASE("falcon assembler: status bytes stripped, one frame per transfer") {
	FalconStreamAssembler assembler;
	const std::vector<uint8_t> in = transfer(GOLDEN_REPLY);
	assembler.push_transfer(in.data(), in.size());
	FalconReply reply;
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == -1447);
	CHECK_FALSE(assembler.pop_reply(reply));
	CHECK(assembler.buffered() == 0);
	CHECK(assembler.counters().frames == 1);
	CHECK(assembler.counters().dropped_bytes == 0);
}

TEST_CASE("falcon assembler: a frame split across two 64-byte reads, and status-only reads between") {
	FalconStreamAssembler assembler;
	const std::vector<uint8_t> frame = reply_bytes(123, -456, 789, 7, 2);
	const std::vector<uint8_t> first = transfer({ frame.begin(), frame.begin() + 5 });
	const std::vector<uint8_t> empty = transfer({});
	const std::vector<uint8_t> second = transfer({ frame.begin() + 5, frame.end() });
	FalconReply reply;
	assembler.push_transfer(first.data(), first.size());
	CHECK_FALSE(assembler.pop_reply(reply));
	CHECK(assembler.buffered() == 5); // The tail is kept.
	assembler.push_transfer(empty.data(), empty.size());
	CHECK_FALSE(assembler.pop_reply(reply));
	assembler.push_transfer(second.data(), second.size());
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == 123);
	CHECK(reply.encoder[1] == -456);
	CHECK(reply.encoder[2] == 789);
	CHECK(reply.buttons == 2);
}

TEST_CASE("falcon assembler: two frames and a partial third in one read - the tail waits for the next") {
	FalconStreamAssembler assembler;
	std::vector<uint8_t> payload = reply_bytes(1, 2, 3);
	const std::vector<uint8_t> second = reply_bytes(4, 5, 6);
	const std::vector<uint8_t> third = reply_bytes(7, 8, 9);
	payload.insert(payload.end(), second.begin(), second.end());
	payload.insert(payload.end(), third.begin(), third.begin() + 9);
	const std::vector<uint8_t> in = transfer(payload);
	assembler.push_transfer(in.data(), in.size());
	FalconReply reply;
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == 1);
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == 4);
	CHECK_FALSE(assembler.pop_reply(reply));
	CHECK(assembler.buffered() == 9);
	const std::vector<uint8_t> rest = transfer({ third.begin() + 9, third.end() });
	assembler.push_transfer(rest.data(), rest.size());
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[2] == 9);
}

TEST_CASE("falcon assembler: a multi-packet transfer carries status bytes at every 64-byte packet") {
	// 128 bytes = two USB packets: status + 62 payload, status + 62 payload. A frame straddles
	// the packet boundary; the second packet's status bytes must not end up inside it.
	std::vector<uint8_t> payload;
	for (int i = 0; i < 7; ++i) {
		const std::vector<uint8_t> frame = reply_bytes(static_cast<int16_t>(100 + i), 0, 0);
		payload.insert(payload.end(), frame.begin(), frame.end());
	}
	payload.resize(124);
	std::vector<uint8_t> in = transfer({ payload.begin(), payload.begin() + 62 });
	const std::vector<uint8_t> packet2 = transfer({ payload.begin() + 62, payload.end() });
	in.insert(in.end(), packet2.begin(), packet2.end());
	REQUIRE(in.size() == 128);
	FalconStreamAssembler assembler;
	assembler.push_transfer(in.data(), in.size());
	FalconReply reply;
	for (int i = 0; i < 7; ++i) {
		REQUIRE(assembler.pop_reply(reply));
		CHECK(reply.encoder[0] == 100 + i);
	}
	CHECK(assembler.counters().malformed_frames == 0);
}

TEST_CASE("falcon assembler: garbage before, between and inside frames is skipped - resync on the next '<'") {
	std::vector<uint8_t> payload = { 0x00, 0xFF, 0x3E, 0x12 }; // Noise, a stray '>'.
	const std::vector<uint8_t> good1 = reply_bytes(11, 12, 13);
	payload.insert(payload.end(), good1.begin(), good1.end());
	// A '<' whose frame is cut short by the next real frame: '<' 'A' 'A' then a full frame.
	payload.insert(payload.end(), { 0x3C, 0x41, 0x41 });
	const std::vector<uint8_t> good2 = reply_bytes(21, 22, 23);
	payload.insert(payload.end(), good2.begin(), good2.end());
	const std::vector<uint8_t> in = transfer(payload);
	FalconStreamAssembler assembler;
	assembler.push_transfer(in.data(), in.size());
	FalconReply reply;
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == 11);
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[0] == 21);
	CHECK_FALSE(assembler.pop_reply(reply));
	CHECK(assembler.counters().malformed_frames == 1);
	CHECK(assembler.counters().dropped_bytes == 4 + 3);
}

TEST_CASE("falcon assembler: transfers shorter than the status bytes are counted, not read") {
	FalconStreamAssembler assembler;
	const uint8_t one = 0x3C;
	assembler.push_transfer(&one, 1);
	assembler.push_transfer(nullptr, 10);
	CHECK(assembler.counters().short_transfers == 1);
	CHECK(assembler.buffered() == 0);
}

TEST_CASE("falcon assembler: overflow keeps the newest bytes") {
	FalconStreamAssembler assembler;
	std::vector<uint8_t> noise(200, 0x41); // No '<' anywhere.
	assembler.push_payload(noise.data(), noise.size());
	CHECK(assembler.buffered() == FalconStreamAssembler::CAPACITY);
	CHECK(assembler.counters().dropped_bytes == 200 - FalconStreamAssembler::CAPACITY);
	const std::vector<uint8_t> frame = reply_bytes(-5, -6, -7);
	assembler.push_payload(frame.data(), frame.size());
	FalconReply reply;
	REQUIRE(assembler.pop_reply(reply));
	CHECK(reply.encoder[2] == -7);
}

TEST_CASE("falcon assembler: fuzz, random streams of frames, garbage and cuts (bounded, ASan/UBSan clean)") {
	std::mt19937 random(0xFA1C0u);
	uint64_t expected_frames = 0;
	uint64_t decoded_valid = 0;
	for (int round = 0; round < 300; ++round) {
		FalconStreamAssembler assembler;
		std::vector<uint8_t> stream;
		std::vector<int16_t> sent;
		for (int piece = 0; piece < 20; ++piece) {
			const int kind = static_cast<int>(random() % 4);
			if (kind == 0) { // Pure noise, may contain '<' and '>'.
				const size_t n = random() % 40;
				for (size_t i = 0; i < n; ++i) {
					stream.push_back(static_cast<uint8_t>(random()));
				}
			} else {
				const int16_t value = static_cast<int16_t>(random());
				const std::vector<uint8_t> frame = reply_bytes(value, static_cast<int16_t>(random()), 0, random() % 8, random() % 16);
				stream.insert(stream.end(), frame.begin(), frame.end());
				if (kind == 3 && !stream.empty()) { // Corrupt one byte of the frame just written.
					stream[stream.size() - 1 - random() % 16] ^= static_cast<uint8_t>(1u + random() % 255u);
				} else {
					sent.push_back(value);
				}
			}
		}
		// Cut into transfers of random sizes (0..62 payload bytes, sometimes multi-packet) and
		// sometimes raw garbage transfers shorter than the status bytes.
		size_t at = 0;
		std::vector<int16_t> got;
		while (at < stream.size()) {
			const size_t n = std::min<size_t>(random() % 63, stream.size() - at);
			std::vector<uint8_t> in = transfer({ stream.begin() + static_cast<std::ptrdiff_t>(at),
					stream.begin() + static_cast<std::ptrdiff_t>(at + n) });
			at += n;
			if (random() % 10 == 0) {
				in.resize(random() % 2); // Truncated transfer.
			}
			assembler.push_transfer(in.data(), in.size());
			FalconReply reply;
			while (assembler.pop_reply(reply)) {
				got.push_back(reply.encoder[0]);
				CHECK(reply.homed <= 7);
				CHECK(reply.buttons <= 15);
			}
			CHECK(assembler.buffered() <= FalconStreamAssembler::CAPACITY);
		}
		expected_frames += sent.size();
		// Every reply returned is a valid frame; noise can forge one only by matching the
		// strict byte ranges, and truncated transfers lose frames, so we check the overlap.
		size_t matched = 0;
		for (size_t i = 0, j = 0; i < got.size() && j < sent.size(); ++j) {
			if (got[i] == sent[j]) {
				++matched;
				++i;
			}
		}
		decoded_valid += matched;
	}
	MESSAGE("fuzz: " << decoded_valid << " of " << expected_frames << " intact frames recovered in order");
	// Most intact frames survive (truncated transfers drop some on purpose).
	CHECK(decoded_valid > expected_frames / 2);
}
