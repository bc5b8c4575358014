// DualSense output reports to the byte (docs/devices/dualsense.md). Golden CRCs: the two of its
// "Bluetooth output report 0x31"
// (0x231501B5, 0x247973C8) and more computed with Python's zlib as
// zlib.crc32(bytes([0xA2]) + report[0:74]).

#include "dualsense_test_util.h"

#include "devices/dualsense/dualsense_crc.h"
#include "devices/dualsense/dualsense_report.h"

#include <doctest/doctest.h>

#include <cstring>

namespace haptics::dualsense {

namespace {

struct Expected {
	uint8_t bytes[MAX_OUTPUT_SIZE] = {};
	size_t size = 0;
};

Expected usb_expected() {
	Expected expected;
	expected.bytes[0] = 0x02;
	expected.size = 63;
	return expected;
}

// A BT report around a hand-made common block; the CRC bytes are filled by the caller.
void bt_from_common(const uint8_t (&p_common)[COMMON_SIZE], uint8_t p_sequence, OutputReport &r_report) {
	wrap_bt_report(p_common, p_sequence, r_report);
}

} // namespace

TEST_CASE("dualsense crc: zlib's check value, and the seed is part of the sum") {
	const uint8_t check[] = { '1', '2', '3', '4', '5', '6', '7', '8', '9' };
	CHECK(crc32(check, sizeof(check)) == 0xCBF43926u);
	// crc32_seeded(s, d) is the plain CRC of s followed by d.
	uint8_t seeded[10] = { 0xA2 };
	std::memcpy(seeded + 1, check, sizeof(check));
	CHECK(crc32_seeded(0xA2, check, sizeof(check)) == crc32(seeded, sizeof(seeded)));
	CHECK(crc32_seeded(0xA2, check, sizeof(check)) != crc32(check, sizeof(check)));
	CHECK(crc32(nullptr, 0) == 0u);
	CHECK_FALSE(crc_trailer_ok(CRC_SEED_OUTPUT, check, 4)); // Too short to carry a CRC.
}

TEST_CASE("dualsense report: USB rumble, legacy recipe (flag0 0x03, values halved at bytes 3/4), 63 bytes") {
	OutputState state;
	state.motor_right = 0x80;
	state.motor_left = 0xFF;
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_RUMBLE, RumbleRecipe::LEGACY, block);
	OutputReport report;
	wrap_usb_report(block, report);

	Expected expected = usb_expected();
	expected.bytes[1] = 0x03; // valid_flag0: compatible vibration + haptics select.
	expected.bytes[3] = 0x40; // motor_right (weak) 0x80 >> 1.
	expected.bytes[4] = 0x7F; // motor_left (strong) 0xFF >> 1.
	CHECK(report.size == USB_OUTPUT_SIZE);
	CHECK(report.size == 63);
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);
}

TEST_CASE("dualsense report: USB rumble, improved recipe (flag0 0x02 + flag2 0x04 at byte 39, full values)") {
	OutputState state;
	state.motor_right = 0x80;
	state.motor_left = 0xFF;
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_RUMBLE, RumbleRecipe::IMPROVED, block);
	OutputReport report;
	wrap_usb_report(block, report);

	Expected expected = usb_expected();
	expected.bytes[1] = 0x02;
	expected.bytes[3] = 0x80;
	expected.bytes[4] = 0xFF;
	expected.bytes[39] = 0x04; // valid_flag2: compatible vibration 2.
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);
}

TEST_CASE("dualsense report: USB lightbar (flag1 0x04, bytes 45-47) and player LEDs (flag1 0x10, byte 44)") {
	OutputState state;
	state.lightbar = Rgb{ 0x11, 0x22, 0x33 };
	state.player_leds = 0x04;
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_LIGHTBAR | FIELD_PLAYER_LEDS, RumbleRecipe::IMPROVED, block);
	OutputReport report;
	wrap_usb_report(block, report);

	Expected expected = usb_expected();
	expected.bytes[2] = 0x14;
	expected.bytes[44] = 0x04;
	expected.bytes[45] = 0x11;
	expected.bytes[46] = 0x22;
	expected.bytes[47] = 0x33;
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);
}

TEST_CASE("dualsense report: USB trigger feedback block at bytes 11..21 with flag0 0x04, left at 22..32 with 0x08") {
	OutputState state;
	REQUIRE(trigger_feedback(3, 5, state.right_trigger));
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_RIGHT_TRIGGER, RumbleRecipe::IMPROVED, block);
	OutputReport report;
	wrap_usb_report(block, report);

	Expected expected = usb_expected();
	expected.bytes[1] = 0x04;
	const uint8_t feedback[] = { 0x21, 0xF8, 0x03, 0x00, 0x48, 0x92, 0x24, 0x00, 0x00, 0x00, 0x00 }; // docs/devices/dualsense.md.
	std::memcpy(expected.bytes + 11, feedback, sizeof(feedback));
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);

	state.left_trigger = state.right_trigger;
	encode_common(state, FIELD_LEFT_TRIGGER, RumbleRecipe::IMPROVED, block);
	wrap_usb_report(block, report);
	expected = usb_expected();
	expected.bytes[1] = 0x08;
	std::memcpy(expected.bytes + 22, feedback, sizeof(feedback));
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);
}

TEST_CASE("dualsense report: fields not asked for stay zero, flags included (the pad keeps their state)") {
	OutputState state;
	state.motor_left = 0x55;
	state.lightbar = Rgb{ 1, 2, 3 };
	REQUIRE(trigger_feedback(0, 8, state.right_trigger));
	uint8_t block[COMMON_SIZE];
	encode_common(state, 0, RumbleRecipe::LEGACY, block);
	const uint8_t zero[COMMON_SIZE] = {};
	CHECK_BYTES(block, COMMON_SIZE, zero, COMMON_SIZE);

	encode_common(state, FIELD_LIGHTBAR_SETUP, RumbleRecipe::LEGACY, block);
	uint8_t setup[COMMON_SIZE] = {};
	setup[38] = 0x02; // valid_flag2: lightbar setup.
	setup[41] = 0x02; // LIGHT_OUT.
	CHECK_BYTES(block, COMMON_SIZE, setup, COMMON_SIZE);
}

TEST_CASE("dualsense report: BT golden CRCs of docs/devices/dualsense.md (zero block - rumble block)") {
	uint8_t block[COMMON_SIZE] = {};
	OutputReport report;
	bt_from_common(block, 0, report);
	REQUIRE(report.size == 78);
	CHECK(report.bytes[0] == 0x31);
	CHECK(report.bytes[1] == 0x00);
	CHECK(report.bytes[2] == 0x10);
	const uint8_t zero_crc[] = { 0xB5, 0x01, 0x15, 0x23 };
	CHECK_BYTES(report.bytes + 74, 4, zero_crc, 4);
	CHECK(read_le32(report.bytes + 74) == 0x231501B5u);

	block[0] = 0x03;
	block[2] = 0x40;
	block[3] = 0x80;
	bt_from_common(block, 0, report);
	const uint8_t rumble_crc[] = { 0xC8, 0x73, 0x79, 0x24 };
	CHECK_BYTES(report.bytes + 74, 4, rumble_crc, 4);
	CHECK(bt_output_crc_ok(report.bytes, report.size));
}

TEST_CASE("dualsense report: BT payload at 3, reserved zero, more zlib golden CRCs (sequence, lightbar, trigger)") {
	// Lightbar 11 22 33 at sequence 3: zlib.crc32(b'\xa2' + report[:74]) = 0x6E0A6F88.
	OutputState state;
	state.lightbar = Rgb{ 0x11, 0x22, 0x33 };
	uint8_t block[COMMON_SIZE];
	encode_common(state, FIELD_LIGHTBAR, RumbleRecipe::IMPROVED, block);
	OutputReport report;
	wrap_bt_report(block, 3, report);
	Expected expected;
	expected.size = 78;
	expected.bytes[0] = 0x31;
	expected.bytes[1] = 0x30;
	expected.bytes[2] = 0x10;
	expected.bytes[3 + 1] = 0x04;
	expected.bytes[3 + 44] = 0x11;
	expected.bytes[3 + 45] = 0x22;
	expected.bytes[3 + 46] = 0x33;
	write_le32(expected.bytes + 74, 0x6E0A6F88u);
	CHECK_BYTES(report.bytes, report.size, expected.bytes, expected.size);

	// Right trigger feedback P=3 S=5 at sequence 1: 0xE4BBE34B.
	state = OutputState{};
	REQUIRE(trigger_feedback(3, 5, state.right_trigger));
	encode_common(state, FIELD_RIGHT_TRIGGER, RumbleRecipe::IMPROVED, block);
	wrap_bt_report(block, 1, report);
	CHECK(report.bytes[1] == 0x10);
	CHECK(report.bytes[3 + 10] == 0x21);
	CHECK(read_le32(report.bytes + 74) == 0xE4BBE34Bu);

	// Zero block at sequence 15: 0xDBD76161.
	const uint8_t zero[COMMON_SIZE] = {};
	wrap_bt_report(zero, 15, report);
	CHECK(report.bytes[1] == 0xF0);
	CHECK(read_le32(report.bytes + 74) == 0xDBD76161u);
}

TEST_CASE("dualsense report: BT sequence uses the low nibble only (16 wraps to 0)") {
	const uint8_t zero[COMMON_SIZE] = {};
	OutputReport report;
	wrap_bt_report(zero, 16, report);
	CHECK(report.bytes[1] == 0x00);
	CHECK(read_le32(report.bytes + 74) == 0x231501B5u);
}

TEST_CASE("dualsense report: a corrupted BT report fails the CRC check, wherever the flip") {
	const uint8_t zero[COMMON_SIZE] = {};
	OutputReport report;
	wrap_bt_report(zero, 5, report);
	REQUIRE(bt_output_crc_ok(report.bytes, report.size));
	for (size_t i = 0; i < BT_OUTPUT_SIZE; ++i) {
		OutputReport corrupt = report;
		corrupt.bytes[i] ^= 0x01;
		CHECK_FALSE(bt_output_crc_ok(corrupt.bytes, corrupt.size));
	}
	CHECK_FALSE(bt_output_crc_ok(report.bytes, 77));
}

TEST_CASE("dualsense report: rumble recipe from the firmware's update version (SDL: >= 0x0224, unknown, Edge)") {
	CHECK(rumble_recipe(0x0223, false) == RumbleRecipe::LEGACY);
	CHECK(rumble_recipe(0x0100, false) == RumbleRecipe::LEGACY);
	CHECK(rumble_recipe(0x0224, false) == RumbleRecipe::IMPROVED);
	CHECK(rumble_recipe(0x0300, false) == RumbleRecipe::IMPROVED);
	CHECK(rumble_recipe(0, false) == RumbleRecipe::IMPROVED); // Unknown: assumed updated.
	CHECK(rumble_recipe(0x0100, true) == RumbleRecipe::IMPROVED); // Edge: always.
}

} // namespace haptics::dualsense
