// DualSense input and feature reports (docs/devices/dualsense.md, "Input reports"; PS-K): USB
// and BT decoding, the BT
// CRC (seed 0xA1; golden values from Python zlib), short/garbled reports, the bus guess,
// firmware info, and a bounded fuzz loop (run it under ASan/UBSan).

#include "devices/dualsense/dualsense_crc.h"
#include "devices/dualsense/dualsense_input.h"

#include <doctest/doctest.h>

#include <cstring>

namespace haptics::dualsense {

namespace {

// USB 0x01: stick x/y, hat, buttons as the pad lays them out (PS-K).
void usb_report(uint8_t (&r_report)[USB_INPUT_SIZE], uint8_t p_x, uint8_t p_y, uint8_t p_buttons0, uint8_t p_buttons1,
		uint8_t p_buttons2) {
	std::memset(r_report, 0, sizeof(r_report));
	r_report[0] = 0x01;
	r_report[1] = p_x;
	r_report[2] = p_y;
	r_report[3] = 0x80;
	r_report[4] = 0x80;
	r_report[8] = p_buttons0;
	r_report[9] = p_buttons1;
	r_report[10] = p_buttons2;
}

void bt_report(uint8_t (&r_report)[BT_INPUT_SIZE], uint8_t p_x, uint8_t p_y, uint8_t p_buttons0, uint8_t p_buttons1) {
	std::memset(r_report, 0, sizeof(r_report));
	r_report[0] = 0x31;
	r_report[2] = p_x;
	r_report[3] = p_y;
	r_report[4] = 0x80;
	r_report[5] = 0x80;
	r_report[2 + 7] = p_buttons0;
	r_report[2 + 8] = p_buttons1;
	write_le32(r_report + 74, crc32_seeded(CRC_SEED_INPUT, r_report, 74));
}

} // namespace

TEST_CASE("dualsense input: USB report 0x01 - sticks, face buttons, shoulders, d-pad, battery") {
	uint8_t report[USB_INPUT_SIZE];
	// Hat 2 (right), cross (0x20) + triangle (0x80); L1 (0x01) + options (0x20); PS (0x01).
	usb_report(report, 0xFF, 0x00, 0x02 | 0x20 | 0x80, 0x01 | 0x20, 0x01);
	report[1 + 52] = 0x17; // Charging state 1, battery 7.
	PadInput input;
	REQUIRE(decode_input_report(report, sizeof(report), Bus::USB, input) == InputDecode::OK);
	CHECK(input.left_x == 0xFF);
	CHECK(input.left_y == 0x00);
	CHECK(input.buttons ==
			((1u << BUTTON_CROSS) | (1u << BUTTON_TRIANGLE) | (1u << BUTTON_L1) | (1u << BUTTON_OPTIONS) | (1u << BUTTON_PS) |
					(1u << BUTTON_DPAD_RIGHT)));
	CHECK(input.battery == 7);
	CHECK(input.charging == 1);
}

TEST_CASE("dualsense input: every button bit and the eight hat directions") {
	struct Case {
		size_t byte;
		uint8_t mask;
		Button button;
	};
	const Case cases[] = {
		{ 0, 0x10, BUTTON_SQUARE },
		{ 0, 0x20, BUTTON_CROSS },
		{ 0, 0x40, BUTTON_CIRCLE },
		{ 0, 0x80, BUTTON_TRIANGLE },
		{ 1, 0x01, BUTTON_L1 },
		{ 1, 0x02, BUTTON_R1 },
		{ 1, 0x04, BUTTON_L2 },
		{ 1, 0x08, BUTTON_R2 },
		{ 1, 0x10, BUTTON_CREATE },
		{ 1, 0x20, BUTTON_OPTIONS },
		{ 1, 0x40, BUTTON_L3 },
		{ 1, 0x80, BUTTON_R3 },
		{ 2, 0x01, BUTTON_PS },
		{ 2, 0x02, BUTTON_TOUCHPAD },
		{ 2, 0x04, BUTTON_MIC_MUTE },
	};
	for (const Case &c : cases) {
		CAPTURE(c.button);
		uint8_t report[USB_INPUT_SIZE];
		usb_report(report, 0x80, 0x80, 0x08, 0, 0); // Hat released.
		report[8 + c.byte] |= c.mask;
		PadInput input;
		REQUIRE(decode_input_report(report, sizeof(report), Bus::USB, input) == InputDecode::OK);
		CHECK(input.buttons == (1u << c.button));
	}
	const uint32_t up = 1u << BUTTON_DPAD_UP, right = 1u << BUTTON_DPAD_RIGHT;
	const uint32_t down = 1u << BUTTON_DPAD_DOWN, left = 1u << BUTTON_DPAD_LEFT;
	const uint32_t hats[] = { up, up | right, right, down | right, down, down | left, left, up | left };
	for (uint8_t hat = 0; hat < 16; ++hat) {
		CAPTURE(hat);
		uint8_t report[USB_INPUT_SIZE];
		usb_report(report, 0x80, 0x80, hat, 0, 0);
		PadInput input;
		REQUIRE(decode_input_report(report, sizeof(report), Bus::USB, input) == InputDecode::OK);
		CHECK(input.buttons == (hat < 8 ? hats[hat] : 0u));
	}
}

TEST_CASE("dualsense input: BT report 0x31 with its seed-0xA1 CRC (zlib golden values)") {
	uint8_t report[BT_INPUT_SIZE];
	bt_report(report, 0x80, 0x80, 0x08, 0);
	CHECK(read_le32(report + 74) == 0x34E3D165u); // zlib.crc32(b'\xa1' + report[:74])
	PadInput input;
	REQUIRE(decode_input_report(report, sizeof(report), Bus::BLUETOOTH, input) == InputDecode::OK);
	CHECK(input.left_x == 0x80);
	CHECK(input.buttons == 0u);

	bt_report(report, 0xFF, 0x00, 0x28, 0x01); // Cross, hat 8, L1.
	CHECK(read_le32(report + 74) == 0xFCE00E1Fu);
	REQUIRE(decode_input_report(report, sizeof(report), Bus::BLUETOOTH, input) == InputDecode::OK);
	CHECK(input.left_x == 0xFF);
	CHECK(input.left_y == 0x00);
	CHECK(input.buttons == ((1u << BUTTON_CROSS) | (1u << BUTTON_L1)));
}

TEST_CASE("dualsense input: a BT report with a bad CRC is dropped and the previous input kept") {
	uint8_t report[BT_INPUT_SIZE];
	bt_report(report, 0x10, 0x20, 0x08, 0);
	PadInput input;
	input.left_x = 0x42;
	report[2] ^= 0x01; // The stick byte changed in flight.
	CHECK(decode_input_report(report, sizeof(report), Bus::BLUETOOTH, input) == InputDecode::BAD_CRC);
	CHECK(input.left_x == 0x42);
	bt_report(report, 0x10, 0x20, 0x08, 0);
	report[76] ^= 0x80; // The CRC itself.
	CHECK(decode_input_report(report, sizeof(report), Bus::BLUETOOTH, input) == InputDecode::BAD_CRC);
	// A CRC with the wrong seed (the output seed) is as bad as a wrong one.
	bt_report(report, 0x10, 0x20, 0x08, 0);
	write_le32(report + 74, crc32_seeded(CRC_SEED_OUTPUT, report, 74));
	CHECK(decode_input_report(report, sizeof(report), Bus::BLUETOOTH, input) == InputDecode::BAD_CRC);
}

TEST_CASE("dualsense input: short, long, empty and foreign reports are rejected without reading past the end") {
	PadInput input;
	input.left_x = 0x42;
	uint8_t usb[USB_INPUT_SIZE];
	usb_report(usb, 0, 0, 0, 0, 0);
	for (size_t size = 1; size < USB_INPUT_SIZE; ++size) {
		CAPTURE(size);
		// A short 0x01 is the BT simple report on BT, and a wrong size on USB.
		CHECK(decode_input_report(usb, size, Bus::USB, input) == InputDecode::WRONG_SIZE);
	}
	uint8_t bt[BT_INPUT_SIZE];
	bt_report(bt, 0, 0, 0, 0);
	for (size_t size = 1; size < BT_INPUT_SIZE; ++size) {
		CHECK(decode_input_report(bt, size, Bus::BLUETOOTH, input) == InputDecode::WRONG_SIZE);
	}
	CHECK(decode_input_report(usb, 0, Bus::USB, input) == InputDecode::EMPTY);
	CHECK(decode_input_report(nullptr, 64, Bus::USB, input) == InputDecode::EMPTY);
	CHECK(decode_input_report(bt, sizeof(bt), Bus::USB, input) == InputDecode::UNKNOWN_REPORT); // 0x31 on USB.
	CHECK(decode_input_report(usb, sizeof(usb), Bus::BLUETOOTH, input) == InputDecode::WRONG_SIZE); // 64-byte 0x01 on BT.
	const uint8_t simple[10] = { 0x01, 0x80, 0x80, 0x80, 0x80, 0x08, 0, 0, 0, 0 };
	CHECK(decode_input_report(simple, sizeof(simple), Bus::BLUETOOTH, input) == InputDecode::SIMPLE_MODE);
	const uint8_t other[] = { 0x05, 1, 2, 3 };
	CHECK(decode_input_report(other, sizeof(other), Bus::USB, input) == InputDecode::UNKNOWN_REPORT);
	CHECK(input.left_x == 0x42); // Untouched by all of them.
	CHECK(std::strlen(input_decode_name(InputDecode::BAD_CRC)) > 0);
}

TEST_CASE("dualsense input: the bus from the first report (hidapi < 0.13 has no bus_type)") {
	uint8_t usb[USB_INPUT_SIZE];
	usb_report(usb, 0x80, 0x80, 0x08, 0, 0);
	uint8_t bt[BT_INPUT_SIZE];
	bt_report(bt, 0x80, 0x80, 0x08, 0);
	const uint8_t simple[10] = { 0x01 };
	CHECK(bus_from_input_report(usb, sizeof(usb)) == Bus::USB);
	CHECK(bus_from_input_report(bt, sizeof(bt)) == Bus::BLUETOOTH);
	CHECK(bus_from_input_report(simple, sizeof(simple)) == Bus::BLUETOOTH);
	CHECK(bus_from_input_report(bt, 60) == Bus::UNKNOWN);
	CHECK(bus_from_input_report(usb, 0) == Bus::UNKNOWN);
	PadInput input;
	CHECK(decode_input_report(usb, sizeof(usb), Bus::UNKNOWN, input) == InputDecode::OK);
	CHECK(decode_input_report(bt, sizeof(bt), Bus::UNKNOWN, input) == InputDecode::OK);
	CHECK(decode_input_report(bt, 70, Bus::UNKNOWN, input) == InputDecode::WRONG_SIZE);
}

TEST_CASE("dualsense input: firmware info 0x20 - version at bytes 44..45, BT CRC seed 0xA3") {
	uint8_t report[FEATURE_FIRMWARE_INFO_SIZE] = {};
	report[0] = 0x20;
	report[44] = 0x24;
	report[45] = 0x02;
	uint16_t version = 0;
	REQUIRE(parse_firmware_info(report, sizeof(report), Bus::USB, version) == FirmwareInfoParse::OK);
	CHECK(version == 0x0224);

	// BT: zlib.crc32(b'\xa3' + report[:60]) = 0x36C453A4.
	write_le32(report + 60, 0x36C453A4u);
	version = 0;
	REQUIRE(parse_firmware_info(report, sizeof(report), Bus::BLUETOOTH, version) == FirmwareInfoParse::OK);
	CHECK(version == 0x0224);
	report[44] = 0x10;
	version = 7;
	CHECK(parse_firmware_info(report, sizeof(report), Bus::BLUETOOTH, version) == FirmwareInfoParse::BAD_CRC);
	CHECK(version == 7);
	CHECK(parse_firmware_info(report, 63, Bus::USB, version) == FirmwareInfoParse::WRONG_SIZE);
	report[0] = 0x09;
	CHECK(parse_firmware_info(report, sizeof(report), Bus::USB, version) == FirmwareInfoParse::WRONG_ID);
	CHECK(parse_firmware_info(nullptr, 64, Bus::USB, version) == FirmwareInfoParse::WRONG_SIZE);
}

TEST_CASE("dualsense input: fuzz - random sizes and bytes, valid-looking headers, never a crash or a bad read") {
	// Each report lives in a buffer exactly its size (heap, so ASan sees any overread).
	uint32_t seed = 0xC0FFEEu;
	auto next = [&seed] {
		seed ^= seed << 13;
		seed ^= seed >> 17;
		seed ^= seed << 5;
		return seed;
	};
	int decoded = 0;
	for (int round = 0; round < 20000; ++round) {
		const size_t size = next() % 100;
		auto *report = new uint8_t[size == 0 ? 1 : size];
		for (size_t i = 0; i < size; ++i) {
			report[i] = static_cast<uint8_t>(next());
		}
		if (size > 0 && (round & 3) == 0) {
			report[0] = (round & 4) ? 0x31 : 0x01; // Make the ID checks pass half the time.
		}
		if (size == BT_INPUT_SIZE && (round & 8) == 0) {
			report[0] = 0x31;
			write_le32(report + 74, crc32_seeded(CRC_SEED_INPUT, report, 74)); // Valid CRC, random body.
		}
		const Bus buses[] = { Bus::USB, Bus::BLUETOOTH, Bus::UNKNOWN };
		for (const Bus bus : buses) {
			PadInput input;
			const InputDecode result = decode_input_report(size == 0 ? nullptr : report, size, bus, input);
			decoded += result == InputDecode::OK ? 1 : 0;
			if (result == InputDecode::OK) {
				CHECK(input.battery <= 0x0F);
				CHECK(input.buttons < (1u << BUTTON_COUNT));
			}
		}
		uint16_t version = 0;
		parse_firmware_info(size == 0 ? nullptr : report, size, Bus::BLUETOOTH, version);
		bus_from_input_report(size == 0 ? nullptr : report, size);
		delete[] report;
	}
	CHECK(decoded > 0); // The loop did reach the decoders' full paths.
}

} // namespace haptics::dualsense
