#include "devices/dualsense/dualsense_input.h"

#include "devices/dualsense/dualsense_crc.h"

namespace haptics::dualsense {

namespace {

// d-pad hat 0..7 (up, clockwise) -> our direction bits; 8..15 = released (PS-K maps any
// value past the table to centre).
constexpr uint32_t HAT_BITS[8] = {
	1u << BUTTON_DPAD_UP,
	(1u << BUTTON_DPAD_UP) | (1u << BUTTON_DPAD_RIGHT),
	1u << BUTTON_DPAD_RIGHT,
	(1u << BUTTON_DPAD_DOWN) | (1u << BUTTON_DPAD_RIGHT),
	1u << BUTTON_DPAD_DOWN,
	(1u << BUTTON_DPAD_DOWN) | (1u << BUTTON_DPAD_LEFT),
	1u << BUTTON_DPAD_LEFT,
	(1u << BUTTON_DPAD_UP) | (1u << BUTTON_DPAD_LEFT),
};

struct BitMap {
	uint8_t byte; // Index into buttons[].
	uint8_t mask;
	Button button;
};

constexpr BitMap BUTTON_BITS[] = {
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

// p_block points at the common input block, which the caller checked is complete.
void decode_common(const uint8_t *p_block, PadInput &r_input) {
	r_input.left_x = p_block[input::LEFT_STICK_X];
	r_input.left_y = p_block[input::LEFT_STICK_Y];
	r_input.l2 = p_block[input::L2_AXIS];
	r_input.r2 = p_block[input::R2_AXIS];
	r_input.sequence = p_block[input::SEQUENCE];
	const uint8_t *buttons = p_block + input::BUTTONS;
	const uint8_t hat = buttons[0] & 0x0Fu;
	uint32_t bits = hat < 8 ? HAT_BITS[hat] : 0u;
	for (const BitMap &map : BUTTON_BITS) {
		if (buttons[map.byte] & map.mask) {
			bits |= 1u << map.button;
		}
	}
	r_input.buttons = bits;
	r_input.battery = p_block[input::STATUS] & 0x0Fu;
	r_input.charging = static_cast<uint8_t>(p_block[input::STATUS] >> 4);
}

} // namespace

const char *input_decode_name(InputDecode p_result) {
	switch (p_result) {
		case InputDecode::OK:
			return "ok";
		case InputDecode::SIMPLE_MODE:
			return "simple-mode report (pad not yet switched to full reports)";
		case InputDecode::EMPTY:
			return "empty report";
		case InputDecode::WRONG_SIZE:
			return "report of the wrong size";
		case InputDecode::UNKNOWN_REPORT:
			return "unknown report ID";
		case InputDecode::BAD_CRC:
			return "bad CRC";
	}
	return "?";
}

Bus bus_from_input_report(const uint8_t *p_report, size_t p_size) {
	if (p_report == nullptr || p_size == 0) {
		return Bus::UNKNOWN;
	}
	if (p_report[0] == USB_INPUT_REPORT_ID && p_size == USB_INPUT_SIZE) {
		return Bus::USB;
	}
	if ((p_report[0] == BT_INPUT_REPORT_ID && p_size == BT_INPUT_SIZE) ||
			(p_report[0] == BT_SIMPLE_INPUT_REPORT_ID && p_size < USB_INPUT_SIZE)) {
		return Bus::BLUETOOTH;
	}
	return Bus::UNKNOWN;
}

InputDecode decode_input_report(const uint8_t *p_report, size_t p_size, Bus p_bus, PadInput &r_input) {
	if (p_report == nullptr || p_size == 0) {
		return InputDecode::EMPTY;
	}
	const Bus bus = p_bus == Bus::UNKNOWN ? bus_from_input_report(p_report, p_size) : p_bus;
	const uint8_t id = p_report[0];
	if (bus == Bus::USB && id == USB_INPUT_REPORT_ID) {
		if (p_size != USB_INPUT_SIZE) {
			return InputDecode::WRONG_SIZE;
		}
		decode_common(p_report + USB_INPUT_OFFSET, r_input);
		return InputDecode::OK;
	}
	if (bus == Bus::BLUETOOTH && id == BT_INPUT_REPORT_ID) {
		if (p_size != BT_INPUT_SIZE) {
			return InputDecode::WRONG_SIZE;
		}
		if (!crc_trailer_ok(CRC_SEED_INPUT, p_report, p_size)) {
			return InputDecode::BAD_CRC;
		}
		decode_common(p_report + BT_INPUT_OFFSET, r_input);
		return InputDecode::OK;
	}
	if (bus == Bus::BLUETOOTH && id == BT_SIMPLE_INPUT_REPORT_ID) {
		return p_size < USB_INPUT_SIZE ? InputDecode::SIMPLE_MODE : InputDecode::WRONG_SIZE;
	}
	return bus == Bus::UNKNOWN && (id == USB_INPUT_REPORT_ID || id == BT_INPUT_REPORT_ID) ? InputDecode::WRONG_SIZE
																						  : InputDecode::UNKNOWN_REPORT;
}

const char *firmware_info_parse_name(FirmwareInfoParse p_result) {
	switch (p_result) {
		case FirmwareInfoParse::OK:
			return "ok";
		case FirmwareInfoParse::WRONG_SIZE:
			return "wrong size";
		case FirmwareInfoParse::WRONG_ID:
			return "wrong report ID";
		case FirmwareInfoParse::BAD_CRC:
			return "bad CRC";
	}
	return "?";
}

FirmwareInfoParse parse_firmware_info(const uint8_t *p_report, size_t p_size, Bus p_bus, uint16_t &r_update_version) {
	if (p_report == nullptr || p_size != FEATURE_FIRMWARE_INFO_SIZE) {
		return FirmwareInfoParse::WRONG_SIZE;
	}
	if (p_report[0] != FEATURE_FIRMWARE_INFO_ID) {
		return FirmwareInfoParse::WRONG_ID;
	}
	if (p_bus == Bus::BLUETOOTH && !crc_trailer_ok(CRC_SEED_FEATURE, p_report, p_size)) {
		return FirmwareInfoParse::BAD_CRC;
	}
	r_update_version = static_cast<uint16_t>(p_report[FIRMWARE_UPDATE_VERSION_OFFSET] |
			p_report[FIRMWARE_UPDATE_VERSION_OFFSET + 1] << 8);
	return FirmwareInfoParse::OK;
}

} // namespace haptics::dualsense
