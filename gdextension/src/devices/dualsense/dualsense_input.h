#pragma once

// What the pad sends (docs/devices/dualsense.md, "Input reports"; PS-K struct
// dualsense_input_report, dualsense_
// parse_report, dualsense_get_firmware_info):
//
//   USB  report 0x01, exactly 64 bytes: the common input block from byte 1.
//   BT   report 0x31, exactly 78 bytes: the common input block from byte 2, CRC-32 (seed 0xA1)
//        of bytes 0..73 in bytes 74..77 (LE). A report with a bad CRC is dropped, as PS-K does.
//   BT   report 0x01, short: the "simple" report a pad sends until it has received an output
//        report (docs/devices/dualsense.md, "Mode switch"). Not decoded; our first output
//        report switches it.
//
// Common input block: x, y, rx, ry, z (L2), rz (R2), sequence, buttons[4], ..., status at 52
// (low nibble battery 0..10, high nibble charging state). Sticks: 0..255, 0x80 centre, y grows
// DOWNWARD on the pad. Buttons (PS-K DS_BUTTONS*): buttons[0] low nibble = d-pad hat (0 up,
// clockwise to 7 up-left, 8+ released), bit 4 square, 5 cross, 6 circle, 7 triangle;
// buttons[1] L1 R1 L2 R2 create options L3 R3 (bits 0..7); buttons[2] bit 0 PS, 1 touchpad,
// 2 mic mute.
//
// Sizes are checked exactly (the kernel's rule), so a short or garbled report is never read
// past its end; everything here is bounds-checked against p_size.

#include "devices/dualsense/dualsense_bus.h"

#include <cstddef>
#include <cstdint>

namespace haptics::dualsense {

inline constexpr uint8_t USB_INPUT_REPORT_ID = 0x01;
inline constexpr size_t USB_INPUT_SIZE = 64;
inline constexpr size_t USB_INPUT_OFFSET = 1;
inline constexpr uint8_t BT_INPUT_REPORT_ID = 0x31;
inline constexpr size_t BT_INPUT_SIZE = 78;
inline constexpr size_t BT_INPUT_OFFSET = 2;
inline constexpr uint8_t BT_SIMPLE_INPUT_REPORT_ID = 0x01; // Shorter than USB_INPUT_SIZE.
inline constexpr size_t MAX_INPUT_SIZE = BT_INPUT_SIZE;

// Offsets in the common input block.
namespace input {
inline constexpr size_t LEFT_STICK_X = 0;
inline constexpr size_t LEFT_STICK_Y = 1;
inline constexpr size_t L2_AXIS = 4;
inline constexpr size_t R2_AXIS = 5;
inline constexpr size_t SEQUENCE = 6;
inline constexpr size_t BUTTONS = 7; // 4 bytes.
inline constexpr size_t STATUS = 52;
} // namespace input

inline constexpr uint8_t STICK_CENTRE = 0x80;

// DeviceState::buttons bit indices (our order: face buttons first, as games expect).
enum Button : uint32_t {
	BUTTON_CROSS = 0,
	BUTTON_CIRCLE,
	BUTTON_SQUARE,
	BUTTON_TRIANGLE,
	BUTTON_L1,
	BUTTON_R1,
	BUTTON_L2,
	BUTTON_R2,
	BUTTON_CREATE,
	BUTTON_OPTIONS,
	BUTTON_L3,
	BUTTON_R3,
	BUTTON_PS,
	BUTTON_TOUCHPAD,
	BUTTON_MIC_MUTE,
	BUTTON_DPAD_UP,
	BUTTON_DPAD_RIGHT,
	BUTTON_DPAD_DOWN,
	BUTTON_DPAD_LEFT,
	BUTTON_COUNT,
};

struct PadInput {
	uint8_t left_x = STICK_CENTRE;
	uint8_t left_y = STICK_CENTRE; // Grows downward.
	uint8_t l2 = 0; // Trigger pull 0..255.
	uint8_t r2 = 0;
	uint8_t sequence = 0;
	uint32_t buttons = 0; // Bit Button set when pressed.
	uint8_t battery = 0; // 0..10 (tenths), as the pad reports it.
	uint8_t charging = 0; // High nibble of the status byte.
};

enum class InputDecode : int32_t {
	OK = 0,
	SIMPLE_MODE = 1, // BT 0x01 short report: the pad has not switched to full reports yet.
	EMPTY = 2,
	WRONG_SIZE = 3,
	UNKNOWN_REPORT = 4,
	BAD_CRC = 5,
};

const char *input_decode_name(InputDecode p_result);

// The link a report came over, from its ID and size: USB 0x01/64; BT 0x31/78 or the short
// 0x01; UNKNOWN otherwise. For hidapi builds older than 0.13, which lack bus_type.
Bus bus_from_input_report(const uint8_t *p_report, size_t p_size);

// Decodes one input report as hidapi returns it (report ID in byte 0). p_bus UNKNOWN infers
// it per report. r_input is written only on OK.
InputDecode decode_input_report(const uint8_t *p_report, size_t p_size, Bus p_bus, PadInput &r_input);

// Firmware-info feature report 0x20 (PS-K: 64 bytes, update version LE at bytes 44..45;
// on Bluetooth CRC-32 seed 0xA3 over bytes 0..59 in 60..63).
inline constexpr uint8_t FEATURE_FIRMWARE_INFO_ID = 0x20;
inline constexpr size_t FEATURE_FIRMWARE_INFO_SIZE = 64;
inline constexpr size_t FIRMWARE_UPDATE_VERSION_OFFSET = 44;

enum class FirmwareInfoParse : int32_t {
	OK = 0,
	WRONG_SIZE = 1,
	WRONG_ID = 2,
	BAD_CRC = 3,
};

const char *firmware_info_parse_name(FirmwareInfoParse p_result);

// r_update_version is written only on OK.
FirmwareInfoParse parse_firmware_info(const uint8_t *p_report, size_t p_size, Bus p_bus, uint16_t &r_update_version);

} // namespace haptics::dualsense
