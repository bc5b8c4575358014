#pragma once

// Internal to the HID report-descriptor parser (report_descriptor.h): the parser's state
// machine, split over descriptor_parser.cpp (items, globals, locals) and
// descriptor_parser_fields.cpp (main items: fields, collections, the final report table).

#include "devices/hid/report_descriptor.h"

#include <array>
#include <vector>

namespace haptics::hid::detail {

// Item tags (HID 1.11 §6.2.2.4-8).
enum : uint8_t {
	ITEM_MAIN = 0,
	ITEM_GLOBAL = 1,
	ITEM_LOCAL = 2,
	MAIN_INPUT = 0x8,
	MAIN_OUTPUT = 0x9,
	MAIN_COLLECTION = 0xA,
	MAIN_FEATURE = 0xB,
	MAIN_END_COLLECTION = 0xC,
	GLOBAL_USAGE_PAGE = 0x0,
	GLOBAL_LOGICAL_MIN = 0x1,
	GLOBAL_LOGICAL_MAX = 0x2,
	GLOBAL_PHYSICAL_MIN = 0x3,
	GLOBAL_PHYSICAL_MAX = 0x4,
	GLOBAL_UNIT_EXPONENT = 0x5,
	GLOBAL_UNIT = 0x6,
	GLOBAL_REPORT_SIZE = 0x7,
	GLOBAL_REPORT_ID = 0x8,
	GLOBAL_REPORT_COUNT = 0x9,
	GLOBAL_PUSH = 0xA,
	GLOBAL_POP = 0xB,
	LOCAL_USAGE = 0x0,
	LOCAL_USAGE_MIN = 0x1,
	LOCAL_USAGE_MAX = 0x2,
	LOCAL_DELIMITER = 0xA,
	LONG_ITEM_PREFIX = 0xFE,
};

inline int64_t sign_extend_item(uint32_t p_value, uint32_t p_size) {
	switch (p_size) {
		case 1:
			return static_cast<int8_t>(p_value & 0xFF);
		case 2:
			return static_cast<int16_t>(p_value & 0xFFFF);
		case 4:
			return static_cast<int32_t>(p_value);
		default:
			return 0;
	}
}

// A maximum is kept raw until the main item, where its sign follows the minimum's.
struct RawValue {
	uint32_t value = 0;
	uint32_t size = 0;
	int64_t resolve(int64_t p_min) const { return p_min < 0 ? sign_extend_item(value, size) : static_cast<int64_t>(value); }
};

struct GlobalState {
	uint16_t usage_page = 0;
	int64_t logical_min = 0;
	RawValue logical_max;
	int64_t physical_min = 0;
	RawValue physical_max;
	int32_t unit_exponent = 0;
	uint32_t unit = 0;
	uint32_t report_size = 0;
	uint32_t report_count = 0;
	uint8_t report_id = 0;
};

struct LocalState {
	std::vector<uint32_t> usages;
	std::vector<uint8_t> usage_sizes; // 4 = extended (never re-paged).
	uint32_t usage_min = 0;
	bool has_usage_min = false;
	uint32_t delimiter_depth = 0;
	uint32_t delimiter_branch = 0;

	void reset() {
		usages.clear();
		usage_sizes.clear();
		has_usage_min = false;
		delimiter_depth = 0;
		delimiter_branch = 0;
	}
};

class DescriptorParser {
public:
	DescriptorParser(std::span<const uint8_t> p_bytes, const ParseOptions &p_options, ReportDescriptor &r_out) :
			bytes_(p_bytes), options_(p_options), out_(r_out) {}

	Status run();

private:
	Status item_main(uint8_t p_tag, uint32_t p_data);
	Status item_global(uint8_t p_tag, uint32_t p_data, uint32_t p_size);
	Status item_local(uint8_t p_tag, uint32_t p_data, uint32_t p_size);
	Status add_usage(uint32_t p_usage, uint8_t p_size);
	Status add_field(ReportType p_type, uint32_t p_flags);
	Status open_collection(uint32_t p_type);
	Status close_collection();
	Status finish();
	void concatenate_last_usage_page();
	uint32_t logical_usage() const;

	std::span<const uint8_t> bytes_;
	ParseOptions options_;
	ReportDescriptor &out_;
	uint32_t offset_ = 0; // Of the item being parsed.
	GlobalState global_;
	std::vector<GlobalState> global_stack_;
	LocalState local_;
	std::vector<int32_t> collection_stack_;
	// Running bit offsets per (type, id), the ID byte excluded until finish().
	std::array<std::array<uint32_t, 256>, REPORT_TYPE_COUNT> report_bits_{};
	std::array<std::array<bool, 256>, REPORT_TYPE_COUNT> report_seen_{};
	bool main_item_without_id_ = false;
	uint32_t first_main_without_id_offset_ = 0;
};

} // namespace haptics::hid::detail
