#include "devices/hid/joystick_input.h"

#include "devices/hid/report_bits.h"

namespace haptics::hid {

namespace {

constexpr uint16_t PAGE_BUTTON = 0x09;
constexpr uint32_t USAGE_X = make_usage(0x01, 0x30);
constexpr uint32_t USAGE_Y = make_usage(0x01, 0x31);
constexpr uint32_t USAGE_STEERING = make_usage(0x02, 0xC8);

bool find_axis(const ReportDescriptor &p_descriptor, const Report &p_report, uint32_t p_usage, Field &r_field, uint32_t &r_index) {
	for (const Field &field : p_descriptor.report_fields(p_report)) {
		if (!field.is_variable() || field.bit_size == 0 || field.bit_size > 32) {
			continue;
		}
		for (uint32_t j = 0; j < field.count; ++j) {
			if (p_descriptor.usage(field, j) == p_usage) {
				r_field = field;
				r_index = j;
				return true;
			}
		}
	}
	return false;
}

} // namespace

Status JoystickInputLayout::find(const ReportDescriptor &p_descriptor, JoystickInputLayout &r_layout) {
	r_layout = JoystickInputLayout{};
	for (const Report &report : p_descriptor.reports) {
		if (report.type != ReportType::INPUT) {
			continue;
		}
		JoystickInputLayout layout;
		if (!find_axis(p_descriptor, report, USAGE_X, layout.x, layout.x_index) &&
				!find_axis(p_descriptor, report, USAGE_STEERING, layout.x, layout.x_index)) {
			continue;
		}
		layout.has_y = find_axis(p_descriptor, report, USAGE_Y, layout.y, layout.y_index);
		layout.report_id = report.id;
		layout.report_length = report.byte_length;
		for (const Field &field : p_descriptor.report_fields(report)) {
			if (!field.is_variable() || field.bit_size != 1 || layout.button_field_count >= MAX_BUTTON_FIELDS) {
				continue;
			}
			bool any = false;
			uint8_t bits[MAX_BUTTONS];
			for (uint32_t e = 0; e < MAX_BUTTONS; ++e) {
				bits[e] = 0xFF;
				const uint32_t usage = e < field.count ? p_descriptor.usage(field, e) : 0;
				if (usage_page_of(usage) == PAGE_BUTTON && usage_id_of(usage) >= 1 && usage_id_of(usage) <= MAX_BUTTONS) {
					bits[e] = static_cast<uint8_t>(usage_id_of(usage) - 1);
					layout.button_count = usage_id_of(usage) > layout.button_count ? usage_id_of(usage) : layout.button_count;
					any = true;
				}
			}
			if (any) {
				const uint32_t f = layout.button_field_count++;
				layout.button_fields[f] = field;
				for (uint32_t e = 0; e < MAX_BUTTONS; ++e) {
					layout.button_bit[f][e] = bits[e];
				}
			}
		}
		r_layout = layout;
		return Status::success();
	}
	return Status::error(StatusCode::UNSUPPORTED, "HID descriptor has no input report with a Generic Desktop X or Steering axis");
}

double normalise_axis(const Field &p_field, int64_t p_value) {
	const double range = static_cast<double>(p_field.logical_max - p_field.logical_min);
	if (!(range > 0.0)) {
		return 0.0;
	}
	const double value = 2.0 * static_cast<double>(p_value - p_field.logical_min) / range - 1.0;
	return value < -1.0 ? -1.0 : (value > 1.0 ? 1.0 : value);
}

bool decode_joystick_input(const JoystickInputLayout &p_layout, std::span<const uint8_t> p_report, JoystickSample &r_sample) {
	if (p_report.empty() || (p_layout.report_id != 0 && p_report[0] != p_layout.report_id)) {
		return false;
	}
	JoystickSample sample;
	int64_t value = 0;
	if (!read_field_value(p_report, p_layout.x, p_layout.x_index, value)) {
		return false;
	}
	sample.x = normalise_axis(p_layout.x, value);
	if (p_layout.has_y) {
		if (!read_field_value(p_report, p_layout.y, p_layout.y_index, value)) {
			return false;
		}
		sample.y = normalise_axis(p_layout.y, value);
	}
	for (uint32_t f = 0; f < p_layout.button_field_count; ++f) {
		const Field &field = p_layout.button_fields[f];
		const uint32_t count = field.count < JoystickInputLayout::MAX_BUTTONS ? field.count : JoystickInputLayout::MAX_BUTTONS;
		for (uint32_t e = 0; e < count; ++e) {
			const uint8_t bit = p_layout.button_bit[f][e];
			if (bit == 0xFF) {
				continue;
			}
			if (!read_field_value(p_report, field, e, value)) {
				return false;
			}
			sample.buttons |= value != 0 ? (1u << bit) : 0u;
		}
	}
	r_sample = sample;
	return true;
}

} // namespace haptics::hid
