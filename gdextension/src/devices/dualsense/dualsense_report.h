#pragma once

// DualSense output reports (docs/devices/dualsense.md; sources PS-K hid-playstation.c, SDL
// SDL_hidapi_ps5.c, DSC dualsensectl). Both buses carry the same 47-byte COMMON block:
//
//   USB  report 0x02: [0x02][common 47][15 zero bytes]                        = 63 bytes
//   BT   report 0x31: [0x31][seq << 4][0x10][common 47][24 zero][CRC-32 LE]  = 78 bytes
//
// USB length: 63, the size hid-playstation (PS-K DS_OUTPUT_REPORT_USB_SIZE) sends through
// the same hidraw -> usbhid path we use on Linux; SDL's 48 works too. Either fits one 64-byte
// full-speed interrupt packet, so the padding costs no bus time, and matching the kernel's
// bytes means the pad never sees a report shape Linux does not already send it.
//
// Bluetooth: byte 1's high nibble is a sequence number incremented per report and wrapping
// 15 -> 0, low nibble 0; byte 2 is the tag 0x10 ("must be set"); the CRC (dualsense_crc.h,
// seed 0xA2) covers bytes 0..73 and sits at 74..77.
//
// The pad applies only the fields whose valid-flag bit is set; the others keep their state.
// So a report here carries a set of OutputFields: rumble only while we render a rumble of our
// own and once after it ends (the motor bytes are applied by every report that sets the
// rumble bits, zero included, so a report stating zero would stop a rumble Godot's SDL set),
// the rest only when changed or at the keep-alive (dualsense_mapping.h).

#include "devices/dualsense/dualsense_triggers.h"

#include <cstddef>
#include <cstdint>

namespace haptics::dualsense {

inline constexpr size_t COMMON_SIZE = 47;

inline constexpr uint8_t USB_OUTPUT_REPORT_ID = 0x02;
inline constexpr size_t USB_OUTPUT_SIZE = 63;
inline constexpr size_t USB_COMMON_OFFSET = 1; // Report byte = common offset + 1.

inline constexpr uint8_t BT_OUTPUT_REPORT_ID = 0x31;
inline constexpr size_t BT_OUTPUT_SIZE = 78;
inline constexpr uint8_t BT_OUTPUT_TAG = 0x10;
inline constexpr size_t BT_SEQUENCE_OFFSET = 1;
inline constexpr size_t BT_TAG_OFFSET = 2;
inline constexpr size_t BT_COMMON_OFFSET = 3;
inline constexpr size_t BT_CRC_OFFSET = 74;

inline constexpr size_t MAX_OUTPUT_SIZE = BT_OUTPUT_SIZE;

// Offsets in the common block (docs/devices/dualsense.md, "USB output report 0x02"; PS-K
// struct dualsense_output_report_common).
namespace common {
inline constexpr size_t VALID_FLAG0 = 0;
inline constexpr size_t VALID_FLAG1 = 1;
inline constexpr size_t MOTOR_RIGHT = 2; // Weak, high-frequency motor.
inline constexpr size_t MOTOR_LEFT = 3; // Strong, low-frequency motor.
inline constexpr size_t RIGHT_TRIGGER = 10; // 11-byte block (dualsense_triggers.h).
inline constexpr size_t LEFT_TRIGGER = 21;
inline constexpr size_t VALID_FLAG2 = 38;
inline constexpr size_t LIGHTBAR_SETUP = 41;
inline constexpr size_t LED_BRIGHTNESS = 42;
inline constexpr size_t PLAYER_LEDS = 43;
inline constexpr size_t LIGHTBAR_RED = 44;
inline constexpr size_t LIGHTBAR_GREEN = 45;
inline constexpr size_t LIGHTBAR_BLUE = 46;
} // namespace common

// Valid-flag bits (docs/devices/dualsense.md, DSC names).
inline constexpr uint8_t FLAG0_COMPATIBLE_VIBRATION = 0x01;
inline constexpr uint8_t FLAG0_HAPTICS_SELECT = 0x02;
inline constexpr uint8_t FLAG0_RIGHT_TRIGGER = 0x04;
inline constexpr uint8_t FLAG0_LEFT_TRIGGER = 0x08;
inline constexpr uint8_t FLAG1_MIC_MUTE_LED = 0x01;
inline constexpr uint8_t FLAG1_POWER_SAVE = 0x02;
inline constexpr uint8_t FLAG1_LIGHTBAR = 0x04;
inline constexpr uint8_t FLAG1_RELEASE_LEDS = 0x08;
inline constexpr uint8_t FLAG1_PLAYER_LEDS = 0x10;
inline constexpr uint8_t FLAG2_LED_BRIGHTNESS = 0x01;
inline constexpr uint8_t FLAG2_LIGHTBAR_SETUP = 0x02;
inline constexpr uint8_t FLAG2_COMPATIBLE_VIBRATION2 = 0x04;
inline constexpr uint8_t LIGHTBAR_SETUP_LIGHT_OUT = 0x02;

// How the pad wants rumble (docs/devices/dualsense.md, "Rumble recipes"; SDL). Original
// firmware emulates rumble with its
// voice-coil haptics at double strength, so SDL halves the values and sets flag0 bits 0-1
// ("to match Xbox controllers"). From update version 0x0224, when the version is unknown
// (0: SDL assumes an updated pad) and always on the Edge, the improved emulation is
// selected with flag2 bit 2 plus flag0 bit 1 and full values. PS-K switches at 2.21
// (0x0215) instead: only a pad with a version in 0x0215..0x0223 could tell which is right.
enum class RumbleRecipe : int32_t {
	LEGACY = 0,
	IMPROVED = 1,
};

inline constexpr uint16_t IMPROVED_RUMBLE_MIN_VERSION = 0x0224;

RumbleRecipe rumble_recipe(uint16_t p_update_version, bool p_edge);

struct Rgb {
	uint8_t r = 0;
	uint8_t g = 0;
	uint8_t b = 0;
	bool operator==(const Rgb &p_other) const = default;
};

// Everything the backend controls on the pad. Motor values are the levels we want felt
// (0..255); the recipe decides what goes on the wire.
struct OutputState {
	uint8_t motor_left = 0; // Strong, low-frequency.
	uint8_t motor_right = 0; // Weak, high-frequency.
	TriggerEffect right_trigger; // Off by default.
	TriggerEffect left_trigger;
	Rgb lightbar;
	uint8_t player_leds = 0; // Bits 0..4, left to right.
	bool operator==(const OutputState &p_other) const = default;
};

// Which parts of an OutputState a report applies (sets the valid bits of).
enum OutputField : uint32_t {
	FIELD_RUMBLE = 1u << 0,
	FIELD_RIGHT_TRIGGER = 1u << 1,
	FIELD_LEFT_TRIGGER = 1u << 2,
	FIELD_LIGHTBAR = 1u << 3,
	FIELD_PLAYER_LEDS = 1u << 4,
	// Takes the lightbar from the firmware (on Bluetooth it runs its own animation until
	// told; PS-K dualsense_reset_leds): flag2 bit 1 with LIGHT_OUT. Sent once at open.
	FIELD_LIGHTBAR_SETUP = 1u << 5,
	// Everything but the motors: what a keep-alive re-asserts while we have no rumble.
	FIELDS_HELD = FIELD_RIGHT_TRIGGER | FIELD_LEFT_TRIGGER | FIELD_LIGHTBAR | FIELD_PLAYER_LEDS,
	FIELDS_STATE = FIELD_RUMBLE | FIELDS_HELD,
};

// Fills the 47-byte common block (zeroed first) from p_state for p_fields.
void encode_common(const OutputState &p_state, uint32_t p_fields, RumbleRecipe p_recipe, uint8_t (&r_common)[COMMON_SIZE]);

// A report ready for the wire.
struct OutputReport {
	uint8_t bytes[MAX_OUTPUT_SIZE] = {};
	size_t size = 0;
};

// Wraps a common block. The BT form takes the 4-bit sequence number (only its low nibble is
// used) and appends the CRC.
void wrap_usb_report(const uint8_t (&p_common)[COMMON_SIZE], OutputReport &r_report);
void wrap_bt_report(const uint8_t (&p_common)[COMMON_SIZE], uint8_t p_sequence, OutputReport &r_report);

// The CRC a BT output report must carry (seed 0xA2 + bytes 0..73) and whether it does.
uint32_t bt_output_crc(const uint8_t (&p_report)[BT_OUTPUT_SIZE]);
bool bt_output_crc_ok(const uint8_t *p_report, size_t p_size);

} // namespace haptics::dualsense
