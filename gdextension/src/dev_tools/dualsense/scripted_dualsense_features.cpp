#include "dev_tools/dualsense/scripted_dualsense.h"

#include "devices/dualsense/dualsense_crc.h"

#include <cstring>
#include <iterator>

// The pad's feature reports: what hid-playstation reads when it binds (PS-K
// dualsense_get_mac_address, dualsense_get_firmware_info, dualsense_get_calibration_data) and
// what our backend reads at open (firmware info only).

namespace haptics::dualsense {

namespace {

constexpr const char *FEATURE_GONE = "hid_get_feature_report: No such device";
constexpr const char *FEATURE_STALLED = "hid_get_feature_report: Broken pipe";

// Firmware-info fields the kernel prints at bind ("hw_version=0x%08x fw_version=0x%08x").
// Made up: our sources give no real pad's values, and nothing acts on them.
constexpr size_t HARDWARE_VERSION_OFFSET = 24;
constexpr size_t FIRMWARE_VERSION_OFFSET = 28;
constexpr uint32_t HARDWARE_VERSION = 0x00000613;
constexpr uint32_t FIRMWARE_VERSION = 0x01050023;

// IMU calibration, little-endian s16 from byte 1 (PS-K's order): gyro bias pitch/yaw/roll,
// then +/- reference per gyro axis, the reference speed +/- (deg/s), then +/- 1 g per
// accelerometer axis. The driver divides by (plus - minus) for every axis, so no pair may
// be equal: 6.1 has no fallback for a zero range. Values are of a pad at rest on a table:
// small biases, references near +/-8800 counts for 540 deg/s (about 2000 deg/s full scale
// over 16 bits), 8192 counts per g (the driver's DS_ACC_RES_PER_G).
constexpr int16_t CALIBRATION[] = {
	3, -2, 1, // Gyro bias pitch, yaw, roll.
	8815, -8798, // Pitch +, -.
	8807, -8801, // Yaw +, -.
	8792, -8810, // Roll +, -.
	540, 540, // Reference speed +, -.
	8207, -8176, // Accelerometer x +1 g, -1 g.
	8215, -8169, // y.
	8198, -8190, // z.
};
static_assert(1 + sizeof(CALIBRATION) <= FEATURE_CALIBRATION_SIZE);

void put_le16(uint8_t *r_bytes, uint16_t p_value) {
	r_bytes[0] = static_cast<uint8_t>(p_value);
	r_bytes[1] = static_cast<uint8_t>(p_value >> 8);
}

} // namespace

size_t ScriptedDualSense::build_feature(uint8_t p_report_id, uint8_t (&r_report)[FEATURE_MAX_SIZE]) const {
	std::memset(r_report, 0, sizeof(r_report));
	r_report[0] = p_report_id;
	switch (p_report_id) {
		case FEATURE_PAIRING_INFO_ID:
			std::memcpy(r_report + 1, options_.mac_address, sizeof(options_.mac_address));
			return FEATURE_PAIRING_INFO_SIZE;
		case FEATURE_FIRMWARE_INFO_ID:
			write_le32(r_report + HARDWARE_VERSION_OFFSET, HARDWARE_VERSION);
			write_le32(r_report + FIRMWARE_VERSION_OFFSET, FIRMWARE_VERSION);
			put_le16(r_report + FIRMWARE_UPDATE_VERSION_OFFSET, options_.update_version);
			return FEATURE_FIRMWARE_INFO_SIZE;
		case FEATURE_CALIBRATION_ID:
			for (size_t i = 0; i < std::size(CALIBRATION); ++i) {
				put_le16(r_report + 1 + 2 * i, static_cast<uint16_t>(CALIBRATION[i]));
			}
			return FEATURE_CALIBRATION_SIZE;
		default:
			return 0;
	}
}

TransportIo ScriptedDualSense::produce_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size,
		const char *&r_error) {
	r_size = 0;
	if (!plugged()) {
		r_error = FEATURE_GONE;
		return TransportIo::DISCONNECTED;
	}
	feature_reads_.fetch_add(1, std::memory_order_relaxed);
	uint8_t report[FEATURE_MAX_SIZE];
	const size_t size = build_feature(p_report_id, report);
	const bool scripted_failure = options_.firmware_info_fails && p_report_id == FEATURE_FIRMWARE_INFO_ID;
	if (size == 0 || scripted_failure || p_capacity < size) {
		r_error = FEATURE_STALLED;
		return TransportIo::FAILED;
	}
	if (options_.bus == Bus::BLUETOOTH) {
		write_le32(report + size - 4, crc32_seeded(CRC_SEED_FEATURE, report, size - 4));
	}
	std::memcpy(r_buffer, report, size);
	r_size = size;
	return TransportIo::OK;
}

} // namespace haptics::dualsense
