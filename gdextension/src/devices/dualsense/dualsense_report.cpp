#include "devices/dualsense/dualsense_report.h"

#include "devices/dualsense/dualsense_crc.h"

#include <cstring>

namespace haptics::dualsense {

RumbleRecipe rumble_recipe(uint16_t p_update_version, bool p_edge) {
	if (p_edge || p_update_version == 0 || p_update_version >= IMPROVED_RUMBLE_MIN_VERSION) {
		return RumbleRecipe::IMPROVED;
	}
	return RumbleRecipe::LEGACY;
}

void encode_common(const OutputState &p_state, uint32_t p_fields, RumbleRecipe p_recipe, uint8_t (&r_common)[COMMON_SIZE]) {
	std::memset(r_common, 0, sizeof(r_common));
	if (p_fields & FIELD_RUMBLE) {
		if (p_recipe == RumbleRecipe::LEGACY) {
			r_common[common::VALID_FLAG0] |= FLAG0_COMPATIBLE_VIBRATION | FLAG0_HAPTICS_SELECT;
			r_common[common::MOTOR_RIGHT] = static_cast<uint8_t>(p_state.motor_right >> 1);
			r_common[common::MOTOR_LEFT] = static_cast<uint8_t>(p_state.motor_left >> 1);
		} else {
			r_common[common::VALID_FLAG0] |= FLAG0_HAPTICS_SELECT;
			r_common[common::VALID_FLAG2] |= FLAG2_COMPATIBLE_VIBRATION2;
			r_common[common::MOTOR_RIGHT] = p_state.motor_right;
			r_common[common::MOTOR_LEFT] = p_state.motor_left;
		}
	}
	if (p_fields & FIELD_RIGHT_TRIGGER) {
		r_common[common::VALID_FLAG0] |= FLAG0_RIGHT_TRIGGER;
		std::memcpy(r_common + common::RIGHT_TRIGGER, p_state.right_trigger.bytes, TRIGGER_BLOCK_SIZE);
	}
	if (p_fields & FIELD_LEFT_TRIGGER) {
		r_common[common::VALID_FLAG0] |= FLAG0_LEFT_TRIGGER;
		std::memcpy(r_common + common::LEFT_TRIGGER, p_state.left_trigger.bytes, TRIGGER_BLOCK_SIZE);
	}
	if (p_fields & FIELD_LIGHTBAR) {
		r_common[common::VALID_FLAG1] |= FLAG1_LIGHTBAR;
		r_common[common::LIGHTBAR_RED] = p_state.lightbar.r;
		r_common[common::LIGHTBAR_GREEN] = p_state.lightbar.g;
		r_common[common::LIGHTBAR_BLUE] = p_state.lightbar.b;
	}
	if (p_fields & FIELD_PLAYER_LEDS) {
		r_common[common::VALID_FLAG1] |= FLAG1_PLAYER_LEDS;
		r_common[common::PLAYER_LEDS] = p_state.player_leds;
	}
	if (p_fields & FIELD_LIGHTBAR_SETUP) {
		r_common[common::VALID_FLAG2] |= FLAG2_LIGHTBAR_SETUP;
		r_common[common::LIGHTBAR_SETUP] = LIGHTBAR_SETUP_LIGHT_OUT;
	}
}

void wrap_usb_report(const uint8_t (&p_common)[COMMON_SIZE], OutputReport &r_report) {
	std::memset(r_report.bytes, 0, sizeof(r_report.bytes));
	r_report.bytes[0] = USB_OUTPUT_REPORT_ID;
	std::memcpy(r_report.bytes + USB_COMMON_OFFSET, p_common, COMMON_SIZE);
	r_report.size = USB_OUTPUT_SIZE;
}

uint32_t bt_output_crc(const uint8_t (&p_report)[BT_OUTPUT_SIZE]) {
	return crc32_seeded(CRC_SEED_OUTPUT, p_report, BT_CRC_OFFSET);
}

void wrap_bt_report(const uint8_t (&p_common)[COMMON_SIZE], uint8_t p_sequence, OutputReport &r_report) {
	static_assert(sizeof(r_report.bytes) == BT_OUTPUT_SIZE);
	std::memset(r_report.bytes, 0, sizeof(r_report.bytes));
	r_report.bytes[0] = BT_OUTPUT_REPORT_ID;
	r_report.bytes[BT_SEQUENCE_OFFSET] = static_cast<uint8_t>((p_sequence & 0x0Fu) << 4);
	r_report.bytes[BT_TAG_OFFSET] = BT_OUTPUT_TAG;
	std::memcpy(r_report.bytes + BT_COMMON_OFFSET, p_common, COMMON_SIZE);
	write_le32(r_report.bytes + BT_CRC_OFFSET, bt_output_crc(r_report.bytes));
	r_report.size = BT_OUTPUT_SIZE;
}

bool bt_output_crc_ok(const uint8_t *p_report, size_t p_size) {
	return p_size == BT_OUTPUT_SIZE && crc_trailer_ok(CRC_SEED_OUTPUT, p_report, p_size);
}

} // namespace haptics::dualsense
