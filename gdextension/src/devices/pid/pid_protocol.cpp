#include "devices/pid/pid_protocol.h"

#include "devices/hid/report_bits.h"

namespace haptics::pid {

namespace {

int64_t clamp_to_field(int64_t p_value, const hid::Field &p_field) {
	return p_value < p_field.logical_min ? p_field.logical_min : (p_value > p_field.logical_max ? p_field.logical_max : p_value);
}

bool write(const PidLayout &p_layout, const FieldRef &p_ref, int64_t p_value, PidReport &r_report) {
	return hid::write_field_value(r_report.data(), p_layout.field(p_ref), p_ref.index, p_value);
}

bool write_special(const PidLayout &p_layout, int32_t p_field, uint32_t p_index, int64_t p_value, PidReport &r_report) {
	return hid::write_field_value(r_report.data(), p_layout.field(p_field), p_index, p_value);
}

uint8_t command_key(const DeviceControlLayout &p_control, DeviceCommand p_command) {
	switch (p_command) {
		case DeviceCommand::ENABLE_ACTUATORS:
			return p_control.enable_key;
		case DeviceCommand::DISABLE_ACTUATORS:
			return p_control.disable_key;
		case DeviceCommand::STOP_ALL_EFFECTS:
			return p_control.stop_all_key;
		case DeviceCommand::RESET:
			return p_control.reset_key;
		case DeviceCommand::PAUSE:
			return p_control.pause_key;
		case DeviceCommand::CONTINUE:
			return p_control.continue_key;
	}
	return 0;
}

} // namespace

int64_t rescale(int64_t p_value, int64_t p_max, const hid::Field &p_field) {
	return p_value * (p_field.logical_max - p_field.logical_min) / p_max + p_field.logical_min;
}

int64_t scale_direction(uint16_t p_direction, const hid::Field &p_field) {
	return clamp_to_field(rescale(p_direction, 0xFFFF, p_field), p_field);
}

int64_t scale_signed(int16_t p_level, const hid::Field &p_field) {
	int64_t value = 0;
	if (p_field.logical_min < 0) {
		if (p_level > 0) {
			value = int64_t{ p_level } * p_field.logical_max / 0x7FFF;
		} else if (p_level < 0) {
			value = int64_t{ p_level } * p_field.logical_min / -0x8000;
		}
	} else {
		value = p_level < 0 ? rescale(-int64_t{ p_level }, 0x8000, p_field) : rescale(p_level, 0x7FFF, p_field);
	}
	return clamp_to_field(value, p_field);
}

int64_t scale_unsigned(uint16_t p_value, const hid::Field &p_field) {
	return clamp_to_field(rescale(p_value, 0xFFFF, p_field), p_field);
}

const char *device_command_name(DeviceCommand p_command) {
	switch (p_command) {
		case DeviceCommand::ENABLE_ACTUATORS:
			return "Enable Actuators";
		case DeviceCommand::DISABLE_ACTUATORS:
			return "Disable Actuators";
		case DeviceCommand::STOP_ALL_EFFECTS:
			return "Stop All Effects";
		case DeviceCommand::RESET:
			return "Device Reset";
		case DeviceCommand::PAUSE:
			return "Device Pause";
		case DeviceCommand::CONTINUE:
			return "Device Continue";
	}
	return "unknown";
}

void begin_report(const PidLayout &p_layout, int32_t p_report, PidReport &r_report) {
	const hid::Report &report = p_layout.report(p_report);
	r_report = PidReport{};
	r_report.length = static_cast<uint16_t>(report.byte_length); // <= PID_MAX_REPORT_BYTES (build()).
	r_report.bytes[0] = report.id;
}

bool encode_create_constant_effect(const PidLayout &p_layout, PidReport &r_report) {
	begin_report(p_layout, p_layout.create_new_effect_report, r_report);
	return write_special(p_layout, p_layout.create_type_field, 0, p_layout.create_constant_key, r_report);
}

int64_t infinite_duration_value(const PidLayout &p_layout) {
	const hid::Field &field = p_layout.field(p_layout.set_effect.duration);
	if (p_layout.infinite_duration == InfiniteDuration::LOGICAL_MAX) {
		return field.logical_max;
	}
	// K-new: (1 << report_size) - 1; in a signed field those bits read as -1.
	return field.is_signed() ? -1 : static_cast<int64_t>((uint64_t{ 1 } << field.bit_size) - 1);
}

int64_t direction_value(const PidLayout &p_layout, uint16_t p_direction) {
	return scale_direction(p_direction, p_layout.field(p_layout.set_effect.direction_field));
}

int64_t magnitude_value(const PidLayout &p_layout, int16_t p_level) {
	return scale_signed(p_level, p_layout.field(p_layout.set_constant.magnitude));
}

bool encode_set_effect(const PidLayout &p_layout, uint8_t p_block_index, uint16_t p_direction, PidReport &r_report) {
	const SetEffectLayout &layout = p_layout.set_effect;
	begin_report(p_layout, layout.report, r_report);
	bool ok = write(p_layout, layout.block_index, p_block_index, r_report);
	ok = write_special(p_layout, layout.type_field, 0, layout.constant_key, r_report) && ok;
	ok = write(p_layout, layout.duration, infinite_duration_value(p_layout), r_report) && ok;
	// Linux writes 0 to both when the trigger button is unused (beyond the logical range).
	ok = write(p_layout, layout.trigger_button, 0, r_report) && ok;
	ok = write(p_layout, layout.trigger_repeat, 0, r_report) && ok;
	ok = write(p_layout, layout.gain, p_layout.field(layout.gain).logical_max, r_report) && ok;
	ok = write(p_layout, layout.direction_enable, 1, r_report) && ok;
	if (layout.start_delay.found()) {
		ok = write(p_layout, layout.start_delay, 0, r_report) && ok;
	}
	return write_special(p_layout, layout.direction_field, 0, direction_value(p_layout, p_direction), r_report) && ok;
}

bool encode_set_constant_force(const PidLayout &p_layout, uint8_t p_block_index, int16_t p_level, PidReport &r_report) {
	const SetConstantLayout &layout = p_layout.set_constant;
	begin_report(p_layout, layout.report, r_report);
	const bool ok = write(p_layout, layout.block_index, p_block_index, r_report);
	return write(p_layout, layout.magnitude, magnitude_value(p_layout, p_level), r_report) && ok;
}

bool encode_effect_operation(const PidLayout &p_layout, uint8_t p_block_index, EffectOperation p_operation,
		uint8_t p_loop_count, PidReport &r_report) {
	const EffectOperationLayout &layout = p_layout.effect_operation;
	begin_report(p_layout, layout.report, r_report);
	uint8_t key = layout.stop_key;
	if (p_operation == EffectOperation::START) {
		key = layout.start_key;
	} else if (p_operation == EffectOperation::START_SOLO) {
		key = layout.start_solo_key != 0 ? layout.start_solo_key : layout.start_key;
	}
	bool ok = write(p_layout, layout.block_index, p_block_index, r_report);
	ok = write_special(p_layout, layout.operation_field, 0, key, r_report) && ok;
	const hid::Field &loop = p_layout.field(layout.loop_count);
	return write(p_layout, layout.loop_count, clamp_to_field(p_loop_count, loop), r_report) && ok; // K-new clamps.
}

bool encode_block_free(const PidLayout &p_layout, uint8_t p_block_index, PidReport &r_report) {
	begin_report(p_layout, p_layout.block_free_report, r_report);
	return write(p_layout, p_layout.block_free_index, p_block_index, r_report);
}

bool encode_device_control(const PidLayout &p_layout, DeviceCommand p_command, PidReport &r_report) {
	const DeviceControlLayout &control = p_layout.device_control;
	begin_report(p_layout, control.report, r_report);
	const uint8_t key = command_key(control, p_command);
	if (key == 0) {
		return false; // This device has no such command.
	}
	if (control.bitmask) {
		// The report starts zeroed, so every other control bit is already clear.
		return write_special(p_layout, control.field, key - 1u, 1, r_report);
	}
	return write_special(p_layout, control.field, 0, key, r_report);
}

bool encode_device_gain(const PidLayout &p_layout, uint16_t p_gain, PidReport &r_report) {
	begin_report(p_layout, p_layout.device_gain_report, r_report);
	return write(p_layout, p_layout.device_gain, scale_unsigned(p_gain, p_layout.field(p_layout.device_gain)), r_report);
}

const char *block_load_result_name(BlockLoadResult p_result) {
	switch (p_result) {
		case BlockLoadResult::SUCCESS:
			return "Success";
		case BlockLoadResult::FULL:
			return "Full";
		case BlockLoadResult::ERROR:
			return "Error";
		case BlockLoadResult::GARBAGE:
			return "garbage";
	}
	return "unknown";
}

BlockLoadResult decode_block_load(const PidLayout &p_layout, std::span<const uint8_t> p_reply, uint8_t &r_block_index) {
	const BlockLoadLayout &layout = p_layout.block_load;
	const hid::Report &report = p_layout.report(layout.report);
	if (p_reply.empty() || (report.id != 0 && p_reply[0] != report.id)) {
		return BlockLoadResult::GARBAGE;
	}
	int64_t status = 0;
	if (!hid::read_field_value(p_reply, p_layout.field(layout.status_field), 0, status)) {
		return BlockLoadResult::GARBAGE;
	}
	if (status == layout.full_key) {
		return BlockLoadResult::FULL;
	}
	if (status == layout.error_key) {
		return BlockLoadResult::ERROR;
	}
	if (status != layout.success_key) {
		return BlockLoadResult::GARBAGE;
	}
	int64_t index = 0;
	const hid::Field &index_field = p_layout.field(layout.block_index);
	if (!hid::read_field_value(p_reply, index_field, layout.block_index.index, index) || index < index_field.logical_min ||
			index > index_field.logical_max || index < 1 || index > 255) {
		return BlockLoadResult::GARBAGE;
	}
	r_block_index = static_cast<uint8_t>(index);
	return BlockLoadResult::SUCCESS;
}

} // namespace haptics::pid
