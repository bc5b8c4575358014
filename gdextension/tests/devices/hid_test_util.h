#pragma once

// Shared by the HID/PID tests: parse a descriptor and find a field by one of its usages.

#include "devices/hid/report_descriptor.h"

#include <cstdint>
#include <initializer_list>
#include <vector>

namespace haptics::test {

inline hid::ReportDescriptor parse_or_empty(std::span<const uint8_t> p_bytes, bool p_strict, Status *r_status = nullptr) {
	hid::ReportDescriptor descriptor;
	const Status status = hid::ReportDescriptor::parse(p_bytes, hid::ParseOptions{ p_strict }, descriptor);
	if (r_status) {
		*r_status = status;
	}
	return descriptor;
}

inline hid::ReportDescriptor parse_bytes(std::initializer_list<uint8_t> p_bytes, Status *r_status = nullptr, bool p_strict = true) {
	const std::vector<uint8_t> bytes(p_bytes);
	return parse_or_empty(bytes, p_strict, r_status);
}

// The field of report (p_type, p_id) that lists p_usage; nullptr when none does.
inline const hid::Field *find_field(const hid::ReportDescriptor &p_descriptor, hid::ReportType p_type, uint8_t p_id,
		uint32_t p_usage) {
	const hid::Report *report = p_descriptor.find_report(p_type, p_id);
	if (!report) {
		return nullptr;
	}
	for (const hid::Field &field : p_descriptor.report_fields(*report)) {
		for (const uint32_t usage : p_descriptor.field_usages(field)) {
			if (usage == p_usage) {
				return &field;
			}
		}
	}
	return nullptr;
}

} // namespace haptics::test
