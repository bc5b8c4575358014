#pragma once

// Usage IDs of the Physical Interface Device page (0x0F) that the layout finder and the
// scripted firmware use (docs/devices/hid-pid.md, "Usages"; kernel tables [K-old, K-new]).

#include "devices/device_catalog.h"
#include "devices/hid/report_descriptor.h"

#include <cstdint>

namespace haptics::pid {

inline constexpr uint16_t USAGE_PAGE_PID = HID_USAGE_PAGE_PID; // device_catalog.h
inline constexpr uint16_t USAGE_PAGE_GENERIC_DESKTOP = 0x01;
inline constexpr uint16_t USAGE_PAGE_SIMULATION = 0x02;
inline constexpr uint16_t USAGE_PAGE_BUTTON = 0x09;

constexpr uint32_t pid_usage(uint16_t p_id) {
	return hid::make_usage(USAGE_PAGE_PID, p_id);
}

enum PidUsage : uint16_t {
	// Reports (Logical collections).
	SET_EFFECT_REPORT = 0x21,
	SET_ENVELOPE_REPORT = 0x5A,
	SET_CONDITION_REPORT = 0x5F,
	SET_PERIODIC_REPORT = 0x6E,
	SET_CONSTANT_FORCE_REPORT = 0x73,
	SET_RAMP_FORCE_REPORT = 0x74,
	EFFECT_OPERATION_REPORT = 0x77,
	DEVICE_GAIN_REPORT = 0x7D,
	POOL_REPORT = 0x7F,
	BLOCK_LOAD_REPORT = 0x89,
	BLOCK_FREE_REPORT = 0x90,
	DEVICE_CONTROL = 0x96, // The kernel matches the field's collection, not the 0x95 report.
	CREATE_NEW_EFFECT_REPORT = 0xAB,
	// Fields.
	EFFECT_BLOCK_INDEX = 0x22,
	EFFECT_TYPE = 0x25,
	ET_CONSTANT_FORCE = 0x26,
	DURATION = 0x50,
	SAMPLE_PERIOD = 0x51,
	GAIN = 0x52,
	TRIGGER_BUTTON = 0x53,
	TRIGGER_REPEAT_INTERVAL = 0x54,
	AXES_ENABLE = 0x55,
	DIRECTION_ENABLE = 0x56,
	DIRECTION = 0x57,
	MAGNITUDE = 0x70,
	EFFECT_OPERATION = 0x78,
	OP_EFFECT_START = 0x79,
	OP_EFFECT_START_SOLO = 0x7A,
	OP_EFFECT_STOP = 0x7B,
	LOOP_COUNT = 0x7C,
	DEVICE_GAIN = 0x7E,
	RAM_POOL_SIZE = 0x80,
	SIMULTANEOUS_EFFECTS_MAX = 0x83,
	BLOCK_LOAD_STATUS = 0x8B,
	BLOCK_LOAD_SUCCESS = 0x8C,
	BLOCK_LOAD_FULL = 0x8D,
	BLOCK_LOAD_ERROR = 0x8E,
	DC_ENABLE_ACTUATORS = 0x97,
	DC_DISABLE_ACTUATORS = 0x98,
	DC_STOP_ALL_EFFECTS = 0x99,
	DC_DEVICE_RESET = 0x9A,
	DC_DEVICE_PAUSE = 0x9B,
	DC_DEVICE_CONTINUE = 0x9C,
	START_DELAY = 0xA7,
	DEVICE_MANAGED_POOL = 0xA9,
	RAM_POOL_AVAILABLE = 0xAC,
};

// Generic Desktop / Simulation usages the stick input is read from.
inline constexpr uint32_t USAGE_GD_X = hid::make_usage(USAGE_PAGE_GENERIC_DESKTOP, 0x30);
inline constexpr uint32_t USAGE_GD_Y = hid::make_usage(USAGE_PAGE_GENERIC_DESKTOP, 0x31);
inline constexpr uint32_t USAGE_SIM_STEERING = hid::make_usage(USAGE_PAGE_SIMULATION, 0xC8);

} // namespace haptics::pid
