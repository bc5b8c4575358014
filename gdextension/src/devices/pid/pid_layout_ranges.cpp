#include "devices/pid/pid_layout.h"

#include "devices/hid/report_bits.h"
#include "devices/pid/pid_usages.h"

namespace haptics::pid {

// Windows' parsed data keeps an array's maximum where a value keeps its minimum, so a descriptor
// hidapi rebuilds from it (windows/hidapi_descriptor_reconstruct.c) can say N..0 (a SideWinder FF2
// did, issue 38). The minimum is lost; PID selectors count from 1 (hid-pidff requires it).
uint32_t restore_reversed_selector_arrays(hid::ReportDescriptor &r_descriptor) {
	uint32_t restored = 0;
	for (hid::Field &field : r_descriptor.fields) {
		const uint32_t collection = field.logical_usage;
		const bool selector = collection == pid_usage(EFFECT_TYPE) || collection == pid_usage(EFFECT_OPERATION) ||
				collection == pid_usage(BLOCK_LOAD_STATUS) || collection == pid_usage(DEVICE_CONTROL);
		if (!selector || field.is_variable() || field.logical_max != 0 || field.logical_min <= 0) {
			continue;
		}
		if (field.physical_min == field.logical_min && field.physical_max == field.logical_max) {
			field.physical_min = 1; // The parser copied the reversed range (no physical one was given).
			field.physical_max = field.logical_min;
		}
		field.logical_max = field.logical_min;
		field.logical_min = 1;
		++restored;
	}
	return restored;
}

// The encoders write values inside each field's logical range (scaled and clamped, or keys
// and indexes the descriptor itself defines), so a field whose bits hold that range never
// fails an encoder, and one whose bits do not would fail the first effect, long after the
// probe called the device usable. Only the fields we use are checked: a broken field we
// never touch does not stop a device that works.
Status check_field_ranges(const PidLayout &p_layout) {
	struct Used {
		const char *report_name;
		int32_t report;
		int32_t field; // < 0: optional and absent.
		const char *usage_name;
		uint16_t usage;
	};
	const SetEffectLayout &effect = p_layout.set_effect;
	const EffectOperationLayout &operation = p_layout.effect_operation;
	const BlockLoadLayout &load = p_layout.block_load;
	const Used used[] = {
		{ "Set Effect report", effect.report, effect.block_index.field, "Effect Block Index", EFFECT_BLOCK_INDEX },
		{ "Set Effect report", effect.report, effect.type_field, "Effect Type", EFFECT_TYPE },
		{ "Set Effect report", effect.report, effect.duration.field, "Duration", DURATION },
		{ "Set Effect report", effect.report, effect.trigger_button.field, "Trigger Button", TRIGGER_BUTTON },
		{ "Set Effect report", effect.report, effect.trigger_repeat.field, "Trigger Repeat Interval", TRIGGER_REPEAT_INTERVAL },
		{ "Set Effect report", effect.report, effect.gain.field, "Gain", GAIN },
		{ "Set Effect report", effect.report, effect.direction_enable.field, "Direction Enable", DIRECTION_ENABLE },
		{ "Set Effect report", effect.report, effect.start_delay.field, "Start Delay", START_DELAY },
		{ "Set Effect report", effect.report, effect.direction_field, "Direction", DIRECTION },
		{ "Set Constant Force report", p_layout.set_constant.report, p_layout.set_constant.block_index.field, "Effect Block Index", EFFECT_BLOCK_INDEX },
		{ "Set Constant Force report", p_layout.set_constant.report, p_layout.set_constant.magnitude.field, "Magnitude", MAGNITUDE },
		{ "Effect Operation report", operation.report, operation.block_index.field, "Effect Block Index", EFFECT_BLOCK_INDEX },
		{ "Effect Operation report", operation.report, operation.operation_field, "Effect Operation", EFFECT_OPERATION },
		{ "Effect Operation report", operation.report, operation.loop_count.field, "Loop Count", LOOP_COUNT },
		{ "Device Control report", p_layout.device_control.report, p_layout.device_control.field, "Device Control", DEVICE_CONTROL },
		{ "Block Load report", load.report, load.block_index.field, "Effect Block Index", EFFECT_BLOCK_INDEX },
		{ "Block Load report", load.report, load.status_field, "Block Load Status", BLOCK_LOAD_STATUS },
		{ "Create New Effect report", p_layout.create_new_effect_report, p_layout.create_type_field, "Effect Type", EFFECT_TYPE },
		{ "Block Free report", p_layout.block_free_report, p_layout.block_free_index.field, "Effect Block Index", EFFECT_BLOCK_INDEX },
		{ "Device Gain report", p_layout.device_gain_report, p_layout.device_gain.field, "Device Gain", DEVICE_GAIN },
	};
	for (const Used &value : used) {
		if (value.field < 0) {
			continue;
		}
		const hid::Field &field = p_layout.field(value.field);
		if (hid::field_fits(field, field.logical_min) && hid::field_fits(field, field.logical_max)) {
			continue;
		}
		return Status::error(StatusCode::UNSUPPORTED,
				"PID layout: %s %u: %s (0x%02X) has logical range %lld..%lld, which %u %s bits cannot hold (descriptor byte %u)",
				value.report_name, p_layout.report(value.report).id, value.usage_name, value.usage,
				static_cast<long long>(field.logical_min), static_cast<long long>(field.logical_max), field.bit_size,
				field.is_signed() ? "signed" : "unsigned", field.byte_offset);
	}
	return Status::success();
}

} // namespace haptics::pid
