#include "devices/hid/descriptor_parser.h"

#include <algorithm>

namespace haptics::hid::detail {

void DescriptorParser::concatenate_last_usage_page() {
	// Usages declared before a later Usage Page take that page (Linux's rule), walking back
	// from the last usage until one already carries it.
	for (size_t i = local_.usages.size(); i-- > 0;) {
		if (local_.usage_sizes[i] > 2) {
			continue;
		}
		if (usage_page_of(local_.usages[i]) == global_.usage_page) {
			break;
		}
		local_.usages[i] = make_usage(global_.usage_page, usage_id_of(local_.usages[i]));
	}
}

uint32_t DescriptorParser::logical_usage() const {
	for (size_t i = collection_stack_.size(); i-- > 0;) {
		const Collection &collection = out_.collections[static_cast<size_t>(collection_stack_[i])];
		if (collection.type == static_cast<uint8_t>(CollectionType::LOGICAL)) {
			return collection.usage;
		}
	}
	return 0;
}

Status DescriptorParser::add_field(ReportType p_type, uint32_t p_flags) {
	concatenate_last_usage_page();
	const size_t type_index = static_cast<size_t>(p_type);
	const uint8_t id = global_.report_id;
	uint32_t &bits = report_bits_[type_index][id];
	const uint64_t field_bits = static_cast<uint64_t>(global_.report_size) * global_.report_count;
	const uint64_t limit_bits = static_cast<uint64_t>(MAX_REPORT_BYTES - (id != 0 ? 1 : 0)) * 8;
	if (bits + field_bits > limit_bits) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: %s report %u grows past %u bytes at byte %u",
				report_type_name(p_type), id, MAX_REPORT_BYTES, offset_);
	}
	if (id == 0 && !main_item_without_id_) {
		main_item_without_id_ = true;
		first_main_without_id_offset_ = offset_;
	}
	report_seen_[type_index][id] = true;
	const uint32_t offset = bits;
	bits += static_cast<uint32_t>(field_bits);
	if (local_.usages.empty() || field_bits == 0) {
		return Status::success(); // Padding.
	}
	if (out_.fields.size() >= MAX_FIELDS) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: more than %u fields at byte %u", MAX_FIELDS, offset_);
	}
	if (out_.usages.size() + local_.usages.size() > MAX_USAGES) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: more than %u usages at byte %u", MAX_USAGES, offset_);
	}
	Field field;
	field.type = p_type;
	field.report_id = id;
	field.bit_offset = offset;
	field.bit_size = global_.report_size;
	field.count = global_.report_count;
	field.flags = p_flags & 0x1FFu;
	field.logical_min = global_.logical_min;
	field.logical_max = global_.logical_max.resolve(global_.logical_min);
	field.physical_min = global_.physical_min;
	field.physical_max = global_.physical_max.resolve(global_.physical_min);
	if (field.physical_min == 0 && field.physical_max == 0) {
		field.physical_min = field.logical_min; // HID 1.11 §6.2.2.7: 0, 0 means "as logical".
		field.physical_max = field.logical_max;
	}
	field.unit = global_.unit;
	field.unit_exponent = global_.unit_exponent;
	field.usage_first = static_cast<uint32_t>(out_.usages.size());
	field.usage_count = static_cast<uint32_t>(local_.usages.size());
	field.collection = collection_stack_.empty() ? -1 : collection_stack_.back();
	field.logical_usage = logical_usage();
	field.byte_offset = offset_;
	out_.usages.insert(out_.usages.end(), local_.usages.begin(), local_.usages.end());
	out_.fields.push_back(field);
	return Status::success();
}

Status DescriptorParser::open_collection(uint32_t p_type) {
	if (collection_stack_.size() >= MAX_COLLECTION_DEPTH) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: collections nested deeper than %u at byte %u",
				MAX_COLLECTION_DEPTH, offset_);
	}
	if (out_.collections.size() >= MAX_COLLECTIONS) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: more than %u collections at byte %u", MAX_COLLECTIONS,
				offset_);
	}
	concatenate_last_usage_page();
	Collection collection;
	collection.usage = local_.usages.empty() ? 0 : local_.usages.front();
	collection.parent = collection_stack_.empty() ? -1 : collection_stack_.back();
	collection.type = static_cast<uint8_t>(p_type);
	collection.depth = static_cast<uint16_t>(collection_stack_.size());
	collection.byte_offset = offset_;
	collection_stack_.push_back(static_cast<int32_t>(out_.collections.size()));
	out_.collections.push_back(collection);
	return Status::success();
}

Status DescriptorParser::close_collection() {
	if (!collection_stack_.empty()) {
		collection_stack_.pop_back();
		return Status::success();
	}
	if (options_.strict) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"HID descriptor: END_COLLECTION at byte %u closes no open collection (collection stack underflow)", offset_);
	}
	if (out_.quirks.unmatched_end_collections++ == 0) {
		out_.quirks.first_unmatched_end_offset = offset_;
	}
	return Status::success();
}

Status DescriptorParser::finish() {
	// Refused in both modes: descriptors that are cut short (a short read, a size field that
	// undercounts) end inside a collection, and accepting them loses the reports after the
	// cut, which then show up as "no such report" far from the cause. Linux refuses them too
	// (hid_open_report: "unbalanced collection at end of report description"), so no device
	// that works there sends one.
	if (!collection_stack_.empty()) {
		const Collection &open = out_.collections[static_cast<size_t>(collection_stack_.front())];
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"HID descriptor is truncated at byte %zu: %zu collection(s) still open at the end (outermost opened at byte %u)",
				bytes_.size(), collection_stack_.size(), open.byte_offset);
	}
	if (out_.uses_report_ids && main_item_without_id_) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"HID descriptor: main item at byte %u comes before any Report ID in a descriptor that uses report IDs",
				first_main_without_id_offset_);
	}
	for (uint32_t type = 0; type < REPORT_TYPE_COUNT; ++type) {
		for (uint32_t id = 0; id < 256; ++id) {
			if (!report_seen_[type][id]) {
				continue;
			}
			Report report;
			report.type = static_cast<ReportType>(type);
			report.id = static_cast<uint8_t>(id);
			report.bit_length = report_bits_[type][id] + (id != 0 ? 8 : 0);
			report.byte_length = (report.bit_length + 7) / 8;
			out_.reports.push_back(report);
		}
	}
	for (Field &field : out_.fields) {
		field.bit_offset += field.report_id != 0 ? 8 : 0;
	}
	std::stable_sort(out_.fields.begin(), out_.fields.end(), [](const Field &a, const Field &b) {
		return a.type != b.type ? a.type < b.type : a.report_id < b.report_id;
	});
	size_t next = 0;
	for (Report &report : out_.reports) {
		report.first_field = static_cast<uint32_t>(next);
		while (next < out_.fields.size() && out_.fields[next].type == report.type && out_.fields[next].report_id == report.id) {
			++next;
		}
		report.field_count = static_cast<uint32_t>(next) - report.first_field;
	}
	return Status::success();
}

} // namespace haptics::hid::detail
