#include "devices/pid/pid_layout.h"

#include "devices/pid/pid_usages.h"

#include <array>

namespace haptics::pid {

namespace {

using hid::Collection;
using hid::CollectionType;
using hid::Field;
using hid::Report;
using hid::ReportDescriptor;
using hid::ReportType;

// The report usages the kernel classifies by (pidff_reports, docs/devices/hid-pid.md, "Usages"),
// in its order.
constexpr std::array<uint16_t, 13> REPORT_USAGES = {
	SET_EFFECT_REPORT,
	EFFECT_OPERATION_REPORT,
	DEVICE_GAIN_REPORT,
	POOL_REPORT,
	BLOCK_LOAD_REPORT,
	BLOCK_FREE_REPORT,
	DEVICE_CONTROL,
	CREATE_NEW_EFFECT_REPORT,
	SET_ENVELOPE_REPORT,
	SET_CONDITION_REPORT,
	SET_PERIODIC_REPORT,
	SET_CONSTANT_FORCE_REPORT,
	SET_RAMP_FORCE_REPORT,
};

int32_t report_slot(uint32_t p_usage) {
	if (hid::usage_page_of(p_usage) != USAGE_PAGE_PID) {
		return -1;
	}
	for (size_t i = 0; i < REPORT_USAGES.size(); ++i) {
		if (REPORT_USAGES[i] == hid::usage_id_of(p_usage)) {
			return static_cast<int32_t>(i);
		}
	}
	return -1;
}

// pidff_find_reports: classify by the first field's Logical collection, else by the parent
// Logical collection of the first field's collection ("stacked" collections).
void find_reports(const ReportDescriptor &p_descriptor, std::array<int32_t, REPORT_USAGES.size()> &r_slots) {
	r_slots.fill(-1);
	for (const ReportType type : { ReportType::OUTPUT, ReportType::FEATURE }) {
		for (size_t r = 0; r < p_descriptor.reports.size(); ++r) {
			const Report &report = p_descriptor.reports[r];
			if (report.type != type || report.field_count == 0) {
				continue;
			}
			const Field &first = p_descriptor.fields[report.first_field];
			const int32_t direct = report_slot(first.logical_usage);
			if (direct >= 0) {
				r_slots[static_cast<size_t>(direct)] = static_cast<int32_t>(r);
				continue;
			}
			if (first.collection < 0) {
				continue;
			}
			const int32_t parent = p_descriptor.collections[static_cast<size_t>(first.collection)].parent;
			if (parent < 0) {
				continue;
			}
			const Collection &collection = p_descriptor.collections[static_cast<size_t>(parent)];
			if (collection.type != static_cast<uint8_t>(CollectionType::LOGICAL)) {
				continue;
			}
			const int32_t slot = report_slot(collection.usage);
			if (slot >= 0 && r_slots[static_cast<size_t>(slot)] < 0) {
				r_slots[static_cast<size_t>(slot)] = static_cast<int32_t>(r);
			}
		}
	}
}

// pidff_find_fields for one usage: only fields whose usage count matches the report count.
FieldRef find_value(const ReportDescriptor &p_descriptor, const Report &p_report, uint16_t p_usage) {
	for (const Field &field : p_descriptor.report_fields(p_report)) {
		if (field.max_usage() != field.count) {
			continue;
		}
		for (uint32_t j = 0; j < field.max_usage(); ++j) {
			if (p_descriptor.usage(field, j) == pid_usage(p_usage)) {
				return FieldRef{ p_descriptor.field_index(field), j };
			}
		}
	}
	return FieldRef{};
}

// pidff_find_special_field.
int32_t find_special(const ReportDescriptor &p_descriptor, const Report &p_report, uint16_t p_collection_usage,
		bool p_enforce_min) {
	for (const Field &field : p_descriptor.report_fields(p_report)) {
		if (field.logical_usage == pid_usage(p_collection_usage) && field.count > 0 &&
				(!p_enforce_min || field.logical_min == 1)) {
			return p_descriptor.field_index(field);
		}
	}
	return -1;
}

// pidff_find_special_keys: 1-based position of p_usage in the field's usage list; 0 if absent.
uint8_t find_key(const ReportDescriptor &p_descriptor, const Field &p_field, uint16_t p_usage) {
	const uint32_t limit = p_field.max_usage() < 255 ? p_field.max_usage() : 255;
	for (uint32_t j = 0; j < limit; ++j) {
		if (p_descriptor.usage(p_field, j) == pid_usage(p_usage)) {
			return static_cast<uint8_t>(j + 1);
		}
	}
	return 0;
}

Status missing(const char *p_what, uint16_t p_usage) {
	return Status::error(StatusCode::UNSUPPORTED, "PID layout: no %s (0x%02X)", p_what, p_usage);
}

// Values are written with 32-bit helpers into fixed PID_MAX_REPORT_BYTES buffers.
Status check_report(const PidLayout &p_layout, int32_t p_report, const char *p_name) {
	const Report &report = p_layout.report(p_report);
	if (report.byte_length > PID_MAX_REPORT_BYTES) {
		return Status::error(StatusCode::UNSUPPORTED, "PID layout: %s %u is %u bytes (limit %u)", p_name, report.id,
				report.byte_length, PID_MAX_REPORT_BYTES);
	}
	for (const Field &field : p_layout.descriptor.report_fields(report)) {
		if (field.bit_size > 32) {
			return Status::error(StatusCode::UNSUPPORTED, "PID layout: %s %u has a %u-bit value (limit 32)", p_name, report.id,
					field.bit_size);
		}
	}
	return Status::success();
}

Status find_set_effect(PidLayout &r_layout) {
	SetEffectLayout &layout = r_layout.set_effect;
	const ReportDescriptor &descriptor = r_layout.descriptor;
	const Report &report = r_layout.report(layout.report);
	layout.block_index = find_value(descriptor, report, EFFECT_BLOCK_INDEX);
	layout.duration = find_value(descriptor, report, DURATION);
	layout.gain = find_value(descriptor, report, GAIN);
	layout.trigger_button = find_value(descriptor, report, TRIGGER_BUTTON);
	layout.trigger_repeat = find_value(descriptor, report, TRIGGER_REPEAT_INTERVAL);
	layout.direction_enable = find_value(descriptor, report, DIRECTION_ENABLE);
	layout.start_delay = find_value(descriptor, report, START_DELAY);
	const std::array<std::pair<const FieldRef *, uint16_t>, 6> required = { {
			{ &layout.block_index, EFFECT_BLOCK_INDEX },
			{ &layout.duration, DURATION },
			{ &layout.gain, GAIN },
			{ &layout.trigger_button, TRIGGER_BUTTON },
			{ &layout.trigger_repeat, TRIGGER_REPEAT_INTERVAL },
			{ &layout.direction_enable, DIRECTION_ENABLE },
	} };
	for (const auto &[ref, usage] : required) {
		if (!ref->found()) {
			return missing("Set Effect field", usage);
		}
	}
	if (!layout.start_delay.found()) {
		r_layout.quirks |= QUIRK_MISSING_DELAY; // K-old refused such devices; K-new carries on.
	}
	layout.type_field = find_special(descriptor, report, EFFECT_TYPE, true);
	layout.direction_field = find_special(descriptor, report, DIRECTION, false);
	if (layout.type_field < 0) {
		return missing("Set Effect effect-type array with logical minimum 1", EFFECT_TYPE);
	}
	if (layout.direction_field < 0) {
		return missing("Set Effect direction", DIRECTION);
	}
	layout.constant_key = find_key(descriptor, r_layout.field(layout.type_field), ET_CONSTANT_FORCE);
	if (layout.constant_key == 0) {
		return missing("constant-force effect type in Set Effect", ET_CONSTANT_FORCE);
	}
	return Status::success();
}

Status find_control_reports(PidLayout &r_layout) {
	const ReportDescriptor &descriptor = r_layout.descriptor;
	EffectOperationLayout &operation = r_layout.effect_operation;
	const Report &operation_report = r_layout.report(operation.report);
	operation.block_index = find_value(descriptor, operation_report, EFFECT_BLOCK_INDEX);
	operation.loop_count = find_value(descriptor, operation_report, LOOP_COUNT);
	operation.operation_field = find_special(descriptor, operation_report, EFFECT_OPERATION, true);
	if (!operation.block_index.found() || !operation.loop_count.found() || operation.operation_field < 0) {
		return missing("Effect Operation block index, loop count or operation array", EFFECT_OPERATION_REPORT);
	}
	const Field &op_field = r_layout.field(operation.operation_field);
	operation.start_key = find_key(descriptor, op_field, OP_EFFECT_START);
	operation.start_solo_key = find_key(descriptor, op_field, OP_EFFECT_START_SOLO);
	operation.stop_key = find_key(descriptor, op_field, OP_EFFECT_STOP);
	if (operation.start_key == 0 || operation.stop_key == 0) {
		return missing("Effect Start/Stop operation", EFFECT_OPERATION);
	}

	DeviceControlLayout &control = r_layout.device_control;
	const Report &control_report = r_layout.report(control.report);
	control.field = find_special(descriptor, control_report, DEVICE_CONTROL, true);
	if (control.field < 0) {
		// K-new: retry without the logical-minimum rule (bitmask controls are 0..1).
		control.field = find_special(descriptor, control_report, DEVICE_CONTROL, false);
		r_layout.quirks |= control.field >= 0 ? QUIRK_PERMISSIVE_CONTROL : 0u;
	}
	if (control.field < 0) {
		return missing("Device Control field", DEVICE_CONTROL);
	}
	const Field &control_field = r_layout.field(control.field);
	control.bitmask = control_field.is_variable();
	r_layout.quirks |= control.bitmask ? QUIRK_DEVICE_CONTROL_BITMASK : 0u;
	control.enable_key = find_key(descriptor, control_field, DC_ENABLE_ACTUATORS);
	control.disable_key = find_key(descriptor, control_field, DC_DISABLE_ACTUATORS);
	control.stop_all_key = find_key(descriptor, control_field, DC_STOP_ALL_EFFECTS);
	control.reset_key = find_key(descriptor, control_field, DC_DEVICE_RESET);
	control.pause_key = find_key(descriptor, control_field, DC_DEVICE_PAUSE);
	control.continue_key = find_key(descriptor, control_field, DC_DEVICE_CONTINUE);
	if (control.enable_key == 0 || control.stop_all_key == 0 || control.reset_key == 0) {
		return missing("Device Control Enable Actuators / Stop All / Reset", DEVICE_CONTROL);
	}
	if (control.bitmask && (control.enable_key > control_field.count || control.stop_all_key > control_field.count || control.reset_key > control_field.count)) {
		return Status::error(StatusCode::UNSUPPORTED, "PID layout: Device Control bitmask has %u bits, fewer than its keys",
				control_field.count);
	}

	BlockLoadLayout &load = r_layout.block_load;
	const Report &load_report = r_layout.report(load.report);
	load.block_index = find_value(descriptor, load_report, EFFECT_BLOCK_INDEX);
	load.ram_pool_available = find_value(descriptor, load_report, RAM_POOL_AVAILABLE);
	load.status_field = find_special(descriptor, load_report, BLOCK_LOAD_STATUS, true);
	if (!load.block_index.found() || load.status_field < 0) {
		return missing("Block Load block index or status array", BLOCK_LOAD_REPORT);
	}
	const Field &status_field = r_layout.field(load.status_field);
	load.success_key = find_key(descriptor, status_field, BLOCK_LOAD_SUCCESS);
	load.full_key = find_key(descriptor, status_field, BLOCK_LOAD_FULL);
	load.error_key = find_key(descriptor, status_field, BLOCK_LOAD_ERROR);
	if (load.success_key == 0 || load.full_key == 0 || load.error_key == 0) {
		return missing("Block Load Success/Full/Error status", BLOCK_LOAD_STATUS);
	}
	const Field &index_field = r_layout.field(load.block_index);
	const int64_t span = index_field.logical_max - index_field.logical_min + 1;
	if (span < 1) {
		return Status::error(StatusCode::UNSUPPORTED, "PID layout: Block Load block index range %lld..%lld is empty",
				static_cast<long long>(index_field.logical_min), static_cast<long long>(index_field.logical_max));
	}
	r_layout.max_effects = span > PID_EFFECTS_MAX ? PID_EFFECTS_MAX : static_cast<uint32_t>(span);
	return Status::success();
}

} // namespace

Status PidLayout::build(hid::ReportDescriptor &&p_descriptor, PidLayout &r_layout) {
	r_layout = PidLayout{};
	r_layout.descriptor = std::move(p_descriptor);
	if (restore_reversed_selector_arrays(r_layout.descriptor) > 0) {
		r_layout.quirks |= QUIRK_REVERSED_ARRAY_RANGES;
	}
	std::array<int32_t, REPORT_USAGES.size()> slots;
	find_reports(r_layout.descriptor, slots);
	struct Wanted {
		const char *name;
		uint16_t usage;
		int32_t *report;
		bool optional;
	};
	// The pool is never read (AJ frees every effect on a Pool GET): optional for us.
	const std::array<Wanted, 9> wanted = { {
			{ "Set Effect report", SET_EFFECT_REPORT, &r_layout.set_effect.report, false },
			{ "Effect Operation report", EFFECT_OPERATION_REPORT, &r_layout.effect_operation.report, false },
			{ "Device Gain report", DEVICE_GAIN_REPORT, &r_layout.device_gain_report, false },
			{ "Block Load report", BLOCK_LOAD_REPORT, &r_layout.block_load.report, false },
			{ "Block Free report", BLOCK_FREE_REPORT, &r_layout.block_free_report, false },
			{ "Device Control report", DEVICE_CONTROL, &r_layout.device_control.report, false },
			{ "Create New Effect report", CREATE_NEW_EFFECT_REPORT, &r_layout.create_new_effect_report, false },
			{ "Set Constant Force report", SET_CONSTANT_FORCE_REPORT, &r_layout.set_constant.report, false },
			{ "PID Pool report", POOL_REPORT, &r_layout.pool_report, true },
	} };
	for (const Wanted &want : wanted) {
		*want.report = slots[static_cast<size_t>(report_slot(pid_usage(want.usage)))];
		if (*want.report < 0) {
			if (!want.optional) {
				return missing(want.name, want.usage);
			}
			continue;
		}
		const Status status = check_report(r_layout, *want.report, want.name);
		if (!status) {
			return status;
		}
	}
	Status status = find_set_effect(r_layout);
	if (!status) {
		return status;
	}
	status = find_control_reports(r_layout);
	if (!status) {
		return status;
	}
	const hid::ReportDescriptor &descriptor = r_layout.descriptor;
	const Report &constant = r_layout.report(r_layout.set_constant.report);
	r_layout.set_constant.block_index = find_value(descriptor, constant, EFFECT_BLOCK_INDEX);
	r_layout.set_constant.magnitude = find_value(descriptor, constant, MAGNITUDE);
	if (!r_layout.set_constant.block_index.found() || !r_layout.set_constant.magnitude.found()) {
		return missing("Set Constant Force block index or magnitude", SET_CONSTANT_FORCE_REPORT);
	}
	r_layout.block_free_index = find_value(descriptor, r_layout.report(r_layout.block_free_report), EFFECT_BLOCK_INDEX);
	r_layout.device_gain = find_value(descriptor, r_layout.report(r_layout.device_gain_report), DEVICE_GAIN);
	if (!r_layout.block_free_index.found() || !r_layout.device_gain.found()) {
		return missing("Block Free block index or Device Gain field", r_layout.block_free_index.found() ? DEVICE_GAIN : EFFECT_BLOCK_INDEX);
	}
	r_layout.create_type_field = find_special(descriptor, r_layout.report(r_layout.create_new_effect_report), EFFECT_TYPE, true);
	if (r_layout.create_type_field < 0) {
		return missing("Create New Effect effect-type array with logical minimum 1", EFFECT_TYPE);
	}
	r_layout.create_constant_key = find_key(descriptor, r_layout.field(r_layout.create_type_field), ET_CONSTANT_FORCE);
	// The kernel requires both lists to agree (pidff_find_effects): one key for both reports.
	if (r_layout.create_constant_key != r_layout.set_effect.constant_key) {
		return Status::error(StatusCode::UNSUPPORTED,
				"PID layout: constant force is type %u in Create New Effect but %u in Set Effect", r_layout.create_constant_key,
				r_layout.set_effect.constant_key);
	}
	status = check_field_ranges(r_layout);
	if (!status) {
		return status;
	}
	// AJ's firmware ends an effect at its duration unless it is 0x7FFF, its logical maximum
	// (docs/devices/hid-pid.md, "Infinite duration"); its descriptor is recognisable: no Start Delay, 16-bit duration
	// 0..0x7FFF. Elsewhere write what Linux writes, all ones. PidEffect also restarts the
	// effect periodically, so a wrong guess cannot end the force.
	const hid::Field &duration = r_layout.field(r_layout.set_effect.duration);
	if ((r_layout.quirks & QUIRK_MISSING_DELAY) != 0 && duration.bit_size == 16 && duration.logical_max == 0x7FFF) {
		r_layout.quirks |= QUIRK_AJ_FIRMWARE;
		r_layout.infinite_duration = InfiniteDuration::LOGICAL_MAX;
	}
	return Status::success();
}

bool has_pid_layout(std::span<const uint8_t> p_descriptor_bytes, Status *r_reason) {
	hid::ReportDescriptor descriptor;
	Status status = hid::ReportDescriptor::parse(p_descriptor_bytes, hid::ParseOptions{ false }, descriptor);
	PidLayout layout;
	if (status) {
		status = PidLayout::build(std::move(descriptor), layout);
	}
	if (r_reason) {
		*r_reason = status;
	}
	return status.ok();
}

} // namespace haptics::pid
