#include "devices/hid/report_descriptor.h"

#include "devices/hid/descriptor_parser.h"

namespace haptics::hid {

const char *report_type_name(ReportType p_type) {
	switch (p_type) {
		case ReportType::INPUT:
			return "input";
		case ReportType::OUTPUT:
			return "output";
		case ReportType::FEATURE:
			return "feature";
	}
	return "unknown";
}

Status ReportDescriptor::parse(std::span<const uint8_t> p_bytes, const ParseOptions &p_options, ReportDescriptor &r_descriptor) {
	r_descriptor = ReportDescriptor{};
	detail::DescriptorParser parser(p_bytes, p_options, r_descriptor);
	const Status status = parser.run();
	if (!status) {
		r_descriptor = ReportDescriptor{};
	}
	return status;
}

const Report *ReportDescriptor::find_report(ReportType p_type, uint8_t p_id) const {
	for (const Report &report : reports) {
		if (report.type == p_type && report.id == p_id) {
			return &report;
		}
	}
	return nullptr;
}

std::span<const Field> ReportDescriptor::report_fields(const Report &p_report) const {
	return std::span<const Field>(fields).subspan(p_report.first_field, p_report.field_count);
}

std::span<const uint32_t> ReportDescriptor::field_usages(const Field &p_field) const {
	return std::span<const uint32_t>(usages).subspan(p_field.usage_first, p_field.usage_count);
}

uint32_t ReportDescriptor::usage(const Field &p_field, uint32_t p_index) const {
	if (p_field.usage_count == 0) {
		return 0;
	}
	const uint32_t index = p_index < p_field.usage_count ? p_index : p_field.usage_count - 1;
	return usages[p_field.usage_first + index];
}
} // namespace haptics::hid
