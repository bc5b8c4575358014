// The scripted joystick's firmware: how it answers each report the host sends, with the
// firmware's fixed byte layouts (see scripted_pid_joystick.h).

#include "dev_tools/pid/scripted_pid_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace haptics::pid {

namespace {

constexpr ScriptedPidJoystick::Profile AJ_PROFILE = {
	0x01, 7, 1, 2, 3, 5, 0x02, // 16 buttons, X, Y s16; PID State input 2
	0x01, 18, 1, 2, 3, 9, 11, 12, false, 360.0 / 255.0, // Set Effect, u8 direction 0..255
	0x05, 4, 10000, // Set Constant Force
	0x0A, 0x0B, 0x0C, 0x0D, false, // Operation, Free, Control (array), Gain
	0x05, 4, 0x06, 5, 0x07, 5, // Create, Block Load, Pool (features)
	0x7FFF, 0x7FFF, // USB_DURATION_INFINITE
};

constexpr ScriptedPidJoystick::Profile AJ_START_DELAY_PROFILE = {
	0x01, 7, 1, 2, 3, 5, 0x02, //
	0x01, 20, 1, 2, 3, 11, 13, 14, false, 360.0 / 255.0, // Start Delay u16 at 9: the rest 2 later
	0x05, 4, 10000, //
	0x0A, 0x0B, 0x0C, 0x0D, false, //
	0x05, 4, 0x06, 5, 0x07, 5, //
	0x7FFF, 0x7FFF, //
};

constexpr ScriptedPidJoystick::Profile VIRTUAL_PROFILE = {
	0x01, 6, 1, 1, 2, 4, 0x02, // 8 buttons, X, Y s16
	0x01, 16, 1, 2, 3, 11, 13, 14, true, 0.01, // u16 direction, centidegrees
	0x05, 4, 32767, //
	0x0A, 0x0B, 0x0C, 0x0D, true, // Device Control as a bitmask
	0x11, 4, 0x12, 5, 0x13, 5, // OFB's feature IDs
	0x0000, 0xFFFF, // OFB: 0 and 0xFFFF are infinite
};

constexpr ScriptedPidJoystick::Profile VIRTUAL_WHEEL_PROFILE = {
	0x01, 4, 1, 1, 2, NO_AXIS, 0x02, // 8 buttons, X s16
	0x01, 16, 1, 2, 3, 11, 13, 14, true, 0.01, // u16 direction, centidegrees
	0x05, 4, 32767, //
	0x0A, 0x0B, 0x0C, 0x0D, true, // Device Control as a bitmask
	0x11, 4, 0x12, 5, 0x13, 5, // OFB's feature IDs
	0x0000, 0xFFFF, // OFB: 0 and 0xFFFF are infinite
};

uint16_t read_u16(std::span<const uint8_t> p_bytes, size_t p_offset) {
	return static_cast<uint16_t>(p_bytes[p_offset] | (p_bytes[p_offset + 1] << 8));
}

void put_i16(uint8_t *r_bytes, double p_normalised) {
	const double clamped = std::clamp(std::isfinite(p_normalised) ? p_normalised : 0.0, -1.0, 1.0);
	const auto value = static_cast<int16_t>(std::lround(clamped * 32767.0));
	const auto bits = static_cast<uint16_t>(value);
	r_bytes[0] = static_cast<uint8_t>(bits & 0xFF);
	r_bytes[1] = static_cast<uint8_t>(bits >> 8);
}

} // namespace

const ScriptedPidJoystick::Profile &ScriptedPidJoystick::profile_for(ScriptedFirmware p_firmware) {
	switch (p_firmware) {
		case ScriptedFirmware::AJ:
			return AJ_PROFILE;
		case ScriptedFirmware::VIRTUAL:
			return VIRTUAL_PROFILE;
		case ScriptedFirmware::VIRTUAL_WHEEL:
			return VIRTUAL_WHEEL_PROFILE;
		case ScriptedFirmware::AJ_START_DELAY:
			return AJ_START_DELAY_PROFILE;
	}
	return AJ_PROFILE;
}

DeviceIo ScriptedPidJoystick::unplugged(char *r_error) const {
	std::snprintf(r_error, ERROR_CAPACITY, "the device was unplugged (ENODEV)");
	return DeviceIo::DISCONNECTED;
}

void ScriptedPidJoystick::free_all() {
	for (ScriptedEffect &effect : effects_) {
		effect = ScriptedEffect{};
	}
}

void ScriptedPidJoystick::handle_device_control(uint8_t p_value) {
	switch (p_value) {
		case 1:
			actuators_enabled_ = true;
			break;
		case 2:
			actuators_enabled_ = false;
			break;
		case 3:
			for (ScriptedEffect &effect : effects_) {
				effect.playing = false;
			}
			break;
		case 4: // Reset: every effect freed, actuators off until enabled again.
			free_all();
			actuators_enabled_ = false;
			paused_ = false;
			++stats_.device_resets;
			break;
		case 5:
			paused_ = true;
			break;
		case 6:
			paused_ = false;
			break;
		default:
			++stats_.malformed_reports;
			break;
	}
}

void ScriptedPidJoystick::handle_output(std::span<const uint8_t> p_report) {
	const Profile &p = profile_;
	const uint8_t id = p_report[0];
	const auto block = [&](size_t p_offset) -> ScriptedEffect * {
		const uint8_t index = p_report[p_offset];
		return index >= 1 && index <= MAX_EFFECTS ? &effects_[index] : nullptr;
	};
	if (id == p.set_effect_id && p_report.size() >= p.set_effect_length) {
		if (ScriptedEffect *effect = block(p.se_block)) {
			effect->type = p_report[p.se_type];
			effect->duration = read_u16(p_report, p.se_duration);
			effect->duration_infinite = effect->duration == p.infinite_a || effect->duration == p.infinite_b;
			effect->gain = p_report[p.se_gain];
			effect->enable_bits = p_report[p.se_enable];
			effect->direction = p.direction_16bit ? read_u16(p_report, p.se_direction) : p_report[p.se_direction];
			return;
		}
	} else if (id == p.constant_id && p_report.size() >= p.constant_length) {
		if (ScriptedEffect *effect = block(1)) {
			effect->magnitude = static_cast<int16_t>(read_u16(p_report, 2));
			return;
		}
	} else if (id == p.operation_id && p_report.size() >= 4) {
		const uint8_t index = p_report[1];
		if (ScriptedEffect *effect = block(1)) {
			if (p_report[2] == 2) { // Start Solo stops the others.
				for (ScriptedEffect &other : effects_) {
					other.playing = false;
				}
			}
			effect->playing = p_report[2] == 1 || p_report[2] == 2;
			effect->loop_count = p_report[3];
			started_[index] = std::chrono::steady_clock::now();
			return;
		}
	} else if (id == p.free_id && p_report.size() >= 2) {
		if (p_report[1] == 0xFF) {
			free_all();
			return;
		}
		if (ScriptedEffect *effect = block(1)) {
			*effect = ScriptedEffect{};
			return;
		}
	} else if (id == p.control_id && p_report.size() >= 2) {
		if (!p.control_bitmask) {
			handle_device_control(p_report[1]);
			return;
		}
		for (uint8_t bit = 0; bit < 6; ++bit) {
			if ((p_report[1] >> bit) & 1u) {
				handle_device_control(static_cast<uint8_t>(bit + 1));
			}
		}
		return;
	} else if (id == p.gain_id && p_report.size() >= 2) {
		device_gain_ = p_report[1];
		return;
	}
	++stats_.malformed_reports;
}

DeviceIo ScriptedPidJoystick::write_output(std::span<const uint8_t> p_report, char *r_error) {
	const std::lock_guard lock(mutex_);
	if (!plugged_) {
		return unplugged(r_error);
	}
	++stats_.outputs;
	stats_.bytes_to_device += p_report.size();
	record(TransferKind::OUTPUT, p_report);
	if (!p_report.empty()) {
		handle_output(p_report);
	}
	return DeviceIo::OK;
}

DeviceIo ScriptedPidJoystick::send_feature(std::span<const uint8_t> p_report, char *r_error) {
	const std::lock_guard lock(mutex_);
	if (!plugged_) {
		return unplugged(r_error);
	}
	++stats_.feature_sets;
	stats_.bytes_to_device += p_report.size();
	record(TransferKind::FEATURE_SET, p_report);
	if (p_report.size() >= profile_.create_length && p_report[0] == profile_.create_id) {
		// Create New Effect: allocate the first free block now; Block Load reports it.
		pending_block_ = 0;
		pending_status_ = 2; // Full
		for (uint8_t index = 1; index <= MAX_EFFECTS; ++index) {
			if (!effects_[index].allocated) {
				effects_[index] = ScriptedEffect{};
				effects_[index].allocated = true;
				effects_[index].type = p_report[1];
				pending_block_ = index;
				pending_status_ = 1; // Success
				break;
			}
		}
		return DeviceIo::OK;
	}
	++stats_.malformed_reports;
	return DeviceIo::OK;
}

DeviceIo ScriptedPidJoystick::get_feature(std::span<uint8_t> p_buffer, size_t &r_length, char *r_error) {
	const std::lock_guard lock(mutex_);
	r_length = 0;
	if (!plugged_) {
		return unplugged(r_error);
	}
	++stats_.feature_gets;
	if (p_buffer.empty()) {
		std::snprintf(r_error, ERROR_CAPACITY, "GET_REPORT with an empty buffer");
		return DeviceIo::FAILED;
	}
	const uint8_t id = p_buffer[0];
	uint8_t reply[PID_MAX_REPORT_BYTES] = {};
	size_t length = 0;
	if (id == profile_.block_load_id) {
		BlockLoadAnswer answer = BlockLoadAnswer::FIRMWARE;
		if (!block_load_script_.empty()) {
			answer = block_load_script_.front();
			block_load_script_.erase(block_load_script_.begin());
			// Full or Error: this firmware did not keep the block. Garbage or silence: the
			// answer was lost on the way, the allocation stands and a retry reports it.
			if ((answer == BlockLoadAnswer::FULL || answer == BlockLoadAnswer::ERROR) && pending_block_ != 0) {
				effects_[pending_block_] = ScriptedEffect{};
				pending_block_ = 0;
			}
		}
		length = profile_.block_load_length;
		reply[0] = id;
		switch (answer) {
			case BlockLoadAnswer::FIRMWARE:
				reply[1] = pending_block_;
				reply[2] = pending_status_;
				reply[3] = 0xFF; // RAM pool available
				reply[4] = 0xFF;
				break;
			case BlockLoadAnswer::FULL:
				reply[2] = 2;
				break;
			case BlockLoadAnswer::ERROR:
				reply[2] = 3;
				break;
			case BlockLoadAnswer::GARBAGE: {
				const uint32_t variant = garbage_variant_++ % 3;
				reply[0] = variant == 0 ? static_cast<uint8_t>(id ^ 0x5A) : id;
				reply[1] = variant == 2 ? 0 : 1;
				reply[2] = variant == 1 ? 0 : 1;
				break;
			}
			case BlockLoadAnswer::SILENCE:
				record(TransferKind::FEATURE_GET, {});
				std::snprintf(r_error, ERROR_CAPACITY, "GET_REPORT(Feature 0x%02X) got no answer (timeout)", id);
				return DeviceIo::FAILED;
		}
	} else if (id == profile_.pool_id) {
		free_all(); // AJ: getPIDPool calls FreeAllEffects.
		++stats_.pool_reads;
		length = profile_.pool_length;
		reply[0] = id;
		reply[1] = 0xFF; // RAM pool size
		reply[2] = 0xFF;
		reply[3] = MAX_EFFECTS;
		reply[4] = 0x01; // Device Managed Pool
	} else {
		std::snprintf(r_error, ERROR_CAPACITY, "GET_REPORT(Feature 0x%02X): no such report (EPIPE)", id);
		record(TransferKind::FEATURE_GET, {});
		return DeviceIo::FAILED;
	}
	length = std::min(length, p_buffer.size());
	if (length > 0) {
		std::memcpy(p_buffer.data(), reply, length);
	}
	r_length = length;
	stats_.bytes_from_device += length;
	record(TransferKind::FEATURE_GET, std::span<const uint8_t>(reply, length));
	return DeviceIo::OK;
}

DeviceIo ScriptedPidJoystick::read_input(std::span<uint8_t> p_buffer, size_t &r_length, char *r_error) {
	const std::lock_guard lock(mutex_);
	r_length = 0;
	if (!plugged_) {
		return unplugged(r_error);
	}
	// One report per poll, then "nothing new" (the device reports every 1 ms; we are polled
	// once per I/O cycle and drain until empty).
	if (input_sequence_++ % 2 == 1) {
		return DeviceIo::OK;
	}
	uint8_t report[PID_MAX_REPORT_BYTES] = {};
	size_t length = 0;
	if ((input_sequence_ / 2) % 8 == 7) {
		// Now and then the PID State report (input 2), which the stick decoder must skip.
		report[0] = profile_.state_id;
		report[1] = actuators_enabled_ ? 0x02 : 0x00;
		length = 3;
	} else {
		report[0] = profile_.input_id;
		for (uint8_t b = 0; b < profile_.button_bytes; ++b) {
			report[profile_.buttons_offset + b] = static_cast<uint8_t>(buttons_ >> (8 * b));
		}
		put_i16(report + profile_.x_offset, stick_x_);
		if (profile_.y_offset != NO_AXIS) {
			put_i16(report + profile_.y_offset, stick_y_);
		}
		length = profile_.input_length;
	}
	length = std::min(length, p_buffer.size());
	if (length > 0) {
		std::memcpy(p_buffer.data(), report, length);
	}
	r_length = length;
	++stats_.inputs;
	stats_.bytes_from_device += length;
	record(TransferKind::INPUT, std::span<const uint8_t>(report, length));
	return DeviceIo::OK;
}

} // namespace haptics::pid
