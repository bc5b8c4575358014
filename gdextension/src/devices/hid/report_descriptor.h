#pragma once

// A HID report-descriptor parser (HID 1.11 §6.2.2), engine-free and bounded: it turns the
// descriptor bytes into reports keyed by (type, report ID), each with its wire length and
// its fields (bit offset, size, count, ranges, flags, usages, collections), so backends
// find what they drive by usage instead of hard-coding one firmware's byte layout.
//
// It follows Linux hid-core where the spec leaves room, because that is what real devices
// are tested against:
//  - Logical/Physical Maximum are unsigned when the matching minimum is >= 0 (so `26 FF 00`
//    is 255, not -1); resolved at the main item so the item order does not matter.
//  - A Usage of 1-2 bytes takes the Usage Page current at its declaration, and trailing
//    usages are re-paged with the last Usage Page before a main item (descriptors that put
//    the Usage Page after the Usage).
//  - Main items without usages are padding: their bits count toward the report but they
//    produce no field (so "the report's first field" means what the kernel means).
//  - A variable field with fewer usages than values repeats the last usage (usage()).
//
// Untrusted input: every item is bounds-checked and hard limits stop absurd descriptors;
// errors name the byte offset. A descriptor that ends inside an item or inside a collection
// is truncated and refused in both modes, saying so. Strict mode also rejects an
// END_COLLECTION that closes nothing; tolerant mode ignores it (docs/devices/hid-pid.md,
// "AJ's descriptor", quirk 2),
// recording it in quirks.

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace haptics::hid {

inline constexpr size_t MAX_DESCRIPTOR_BYTES = 4096; // HID_MAX_DESCRIPTOR_SIZE [HAPI-lib, docs/devices/hid.md]
inline constexpr uint32_t MAX_COLLECTION_DEPTH = 32;
inline constexpr uint32_t MAX_GLOBAL_STACK_DEPTH = 8; // PUSH nesting (Linux allows 4).
inline constexpr uint32_t MAX_REPORT_SIZE_BITS = 256; // One value (Linux's limit).
inline constexpr uint32_t MAX_REPORT_COUNT = 4096; // Values in one main item.
inline constexpr uint32_t MAX_REPORT_BYTES = 4096; // One report on the wire, ID included.
inline constexpr uint32_t MAX_FIELDS = 512;
inline constexpr uint32_t MAX_USAGES = 8192; // All fields' usages together.
inline constexpr uint32_t MAX_LOCAL_USAGES = 4096; // Before one main item (usage ranges).
inline constexpr uint32_t MAX_COLLECTIONS = 1024;

enum class ReportType : uint8_t {
	INPUT = 0,
	OUTPUT = 1,
	FEATURE = 2,
};
inline constexpr uint32_t REPORT_TYPE_COUNT = 3;
const char *report_type_name(ReportType p_type);

// A full usage: page in the high 16 bits, ID in the low 16 (the 4-byte "extended" form).
constexpr uint32_t make_usage(uint16_t p_page, uint16_t p_id) {
	return (static_cast<uint32_t>(p_page) << 16) | p_id;
}
constexpr uint16_t usage_page_of(uint32_t p_usage) {
	return static_cast<uint16_t>(p_usage >> 16);
}
constexpr uint16_t usage_id_of(uint32_t p_usage) {
	return static_cast<uint16_t>(p_usage & 0xFFFF);
}

enum class CollectionType : uint8_t {
	PHYSICAL = 0,
	APPLICATION = 1,
	LOGICAL = 2,
	REPORT = 3,
	NAMED_ARRAY = 4,
	USAGE_SWITCH = 5,
	USAGE_MODIFIER = 6,
	// 0x07-0x7F reserved, 0x80-0xFF vendor-defined: kept as their raw value.
};

struct Collection {
	uint32_t usage = 0; // The first usage declared before it; 0 when none.
	int32_t parent = -1; // Index into ReportDescriptor::collections, -1 at top level.
	uint8_t type = 0; // CollectionType or the raw vendor value.
	uint16_t depth = 0; // 0 for a top-level collection.
	uint32_t byte_offset = 0; // Of its COLLECTION item.
};

// Main-item data bits (HID 1.11 §6.2.2.5). Bit 1 clear = Array.
enum FieldFlag : uint32_t {
	FIELD_CONSTANT = 1u << 0,
	FIELD_VARIABLE = 1u << 1,
	FIELD_RELATIVE = 1u << 2,
	FIELD_WRAP = 1u << 3,
	FIELD_NONLINEAR = 1u << 4,
	FIELD_NO_PREFERRED = 1u << 5,
	FIELD_NULL_STATE = 1u << 6,
	FIELD_VOLATILE = 1u << 7,
	FIELD_BUFFERED_BYTES = 1u << 8,
};

struct Field {
	ReportType type = ReportType::INPUT;
	uint8_t report_id = 0;
	// From the first byte of the wire report: the report-ID byte counts when the report has
	// an ID, so offsets match hidapi buffers (byte 0 = ID) and docs/devices/hid-pid.md directly.
	uint32_t bit_offset = 0;
	uint32_t bit_size = 0; // Report Size: bits per value.
	uint32_t count = 0; // Report Count: values.
	uint32_t flags = 0; // FieldFlag bits.
	int64_t logical_min = 0;
	int64_t logical_max = 0;
	int64_t physical_min = 0; // Equal to the logical range when the descriptor gave 0, 0.
	int64_t physical_max = 0;
	uint32_t unit = 0;
	int32_t unit_exponent = 0;
	uint32_t usage_first = 0; // Into ReportDescriptor::usages.
	uint32_t usage_count = 0; // Declared usages (an array lists its selectors).
	int32_t collection = -1; // Innermost enclosing collection.
	// Usage of the innermost enclosing Logical collection (Linux field->logical), 0 if none.
	uint32_t logical_usage = 0;
	uint32_t byte_offset = 0; // Of its main item in the descriptor.

	bool is_variable() const { return (flags & FIELD_VARIABLE) != 0; }
	bool is_constant() const { return (flags & FIELD_CONSTANT) != 0; }
	bool is_signed() const { return logical_min < 0; }
	// Linux's maxusage: a variable field with fewer usages than values repeats the last one.
	uint32_t max_usage() const { return usage_count > count ? usage_count : count; }
};

struct Report {
	ReportType type = ReportType::INPUT;
	uint8_t id = 0; // 0 when the descriptor uses no report IDs.
	uint32_t bit_length = 0; // Including the ID byte when id != 0.
	uint32_t byte_length = 0; // On the wire, ID byte included (docs/devices/hid-pid.md).
	uint32_t first_field = 0; // Into ReportDescriptor::fields; fields keep their order.
	uint32_t field_count = 0;
};

struct ParseOptions {
	bool strict = true;
};

// Irregularities a tolerant parse accepted.
struct ParseQuirks {
	uint32_t unmatched_end_collections = 0;
	uint32_t first_unmatched_end_offset = 0;
	uint32_t ignored_items = 0; // Reserved tags skipped in tolerant mode.
	uint32_t long_items = 0; // Long items are skipped (HID 1.11 §6.2.2.3) in both modes.
};

struct ReportDescriptor {
	std::vector<Collection> collections; // In declaration order.
	std::vector<Field> fields; // Grouped by report (reports' order), declaration order within.
	std::vector<uint32_t> usages;
	std::vector<Report> reports; // Sorted by (type, id).
	bool uses_report_ids = false;
	ParseQuirks quirks;

	// Replaces r_descriptor. Errors name the byte offset of the offending item.
	static Status parse(std::span<const uint8_t> p_bytes, const ParseOptions &p_options, ReportDescriptor &r_descriptor);

	const Report *find_report(ReportType p_type, uint8_t p_id) const;
	std::span<const Field> report_fields(const Report &p_report) const;
	std::span<const uint32_t> field_usages(const Field &p_field) const;
	// The usage of value p_index (Linux's rule past the declared usages); 0 when none.
	uint32_t usage(const Field &p_field, uint32_t p_index) const;
	int32_t field_index(const Field &p_field) const { return static_cast<int32_t>(&p_field - fields.data()); }
};

} // namespace haptics::hid
