#include "devices/hid/report_descriptor.h"

#include <algorithm>
#include <array>

namespace haptics::hid {

namespace {

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

int64_t sign_extend_item(uint32_t p_value, uint32_t p_size) {
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

class Parser {
public:
	Parser(std::span<const uint8_t> p_bytes, const ParseOptions &p_options, ReportDescriptor &r_out) :
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

Status Parser::run() {
	if (bytes_.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "HID report descriptor is empty");
	}
	if (bytes_.size() > MAX_DESCRIPTOR_BYTES) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID report descriptor is %zu bytes (limit %zu)", bytes_.size(),
				MAX_DESCRIPTOR_BYTES);
	}
	const size_t length = bytes_.size();
	size_t position = 0;
	while (position < length) {
		offset_ = static_cast<uint32_t>(position);
		const uint8_t prefix = bytes_[position];
		if (prefix == LONG_ITEM_PREFIX) {
			// bDataSize, bLongItemTag, data: no long-item tags are defined, so skip them.
			if (position + 2 >= length) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: long item at byte %u is truncated", offset_);
			}
			const size_t data_size = bytes_[position + 1];
			if (position + 3 + data_size > length) {
				return Status::error(StatusCode::INVALID_ARGUMENT,
						"HID descriptor: long item at byte %u declares %zu data bytes, %zu left", offset_, data_size,
						length - position - 3);
			}
			++out_.quirks.long_items;
			position += 3 + data_size;
			continue;
		}
		const uint32_t size_code = prefix & 0x3u;
		const uint32_t size = size_code == 3 ? 4 : size_code;
		if (position + 1 + size > length) {
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"HID descriptor: item 0x%02X at byte %u needs %u data bytes, %zu left", prefix, offset_, size,
					length - position - 1);
		}
		uint32_t data = 0;
		for (uint32_t i = 0; i < size; ++i) {
			data |= static_cast<uint32_t>(bytes_[position + 1 + i]) << (8 * i);
		}
		const uint8_t type = static_cast<uint8_t>((prefix >> 2) & 0x3u);
		const uint8_t tag = static_cast<uint8_t>(prefix >> 4);
		Status status;
		switch (type) {
			case ITEM_MAIN:
				status = item_main(tag, data);
				break;
			case ITEM_GLOBAL:
				status = item_global(tag, data, size);
				break;
			case ITEM_LOCAL:
				status = item_local(tag, data, size);
				break;
			default:
				if (options_.strict) {
					return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: reserved item type 0x%02X at byte %u",
							prefix, offset_);
				}
				++out_.quirks.ignored_items;
				break;
		}
		if (!status) {
			return status;
		}
		position += 1 + size;
	}
	return finish();
}

Status Parser::item_main(uint8_t p_tag, uint32_t p_data) {
	Status status;
	switch (p_tag) {
		case MAIN_INPUT:
			status = add_field(ReportType::INPUT, p_data);
			break;
		case MAIN_OUTPUT:
			status = add_field(ReportType::OUTPUT, p_data);
			break;
		case MAIN_FEATURE:
			status = add_field(ReportType::FEATURE, p_data);
			break;
		case MAIN_COLLECTION:
			status = open_collection(p_data & 0xFFu);
			break;
		case MAIN_END_COLLECTION:
			status = close_collection();
			break;
		default:
			if (options_.strict) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: unknown main item tag 0x%X at byte %u",
						p_tag, offset_);
			}
			++out_.quirks.ignored_items;
			break;
	}
	local_.reset(); // Local items apply to the next main item only (§6.2.2.8).
	return status;
}

Status Parser::item_global(uint8_t p_tag, uint32_t p_data, uint32_t p_size) {
	switch (p_tag) {
		case GLOBAL_USAGE_PAGE:
			if (p_data > 0xFFFF) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: usage page 0x%X at byte %u exceeds 16 bits",
						p_data, offset_);
			}
			global_.usage_page = static_cast<uint16_t>(p_data);
			return Status::success();
		case GLOBAL_LOGICAL_MIN:
			global_.logical_min = sign_extend_item(p_data, p_size);
			return Status::success();
		case GLOBAL_LOGICAL_MAX:
			global_.logical_max = { p_data, p_size };
			return Status::success();
		case GLOBAL_PHYSICAL_MIN:
			global_.physical_min = sign_extend_item(p_data, p_size);
			return Status::success();
		case GLOBAL_PHYSICAL_MAX:
			global_.physical_max = { p_data, p_size };
			return Status::success();
		case GLOBAL_UNIT_EXPONENT:
			// A 4-bit two's-complement nibble (0xD = -3); larger values are whole-item signed
			// (real descriptors write `55 FD` for -3, FACTS §1.3), as Linux reads them.
			global_.unit_exponent = p_data < 16 ? (p_data >= 8 ? static_cast<int32_t>(p_data) - 16 : static_cast<int32_t>(p_data))
												: static_cast<int32_t>(sign_extend_item(p_data, p_size));
			return Status::success();
		case GLOBAL_UNIT:
			global_.unit = p_data;
			return Status::success();
		case GLOBAL_REPORT_SIZE:
			if (p_data > MAX_REPORT_SIZE_BITS) {
				return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: report size %u bits at byte %u (limit %u)", p_data,
						offset_, MAX_REPORT_SIZE_BITS);
			}
			global_.report_size = p_data;
			return Status::success();
		case GLOBAL_REPORT_ID:
			if (p_data == 0 || p_data > 255) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: report ID %u at byte %u (must be 1..255)",
						p_data, offset_);
			}
			global_.report_id = static_cast<uint8_t>(p_data);
			out_.uses_report_ids = true;
			return Status::success();
		case GLOBAL_REPORT_COUNT:
			if (p_data > MAX_REPORT_COUNT) {
				return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: report count %u at byte %u (limit %u)", p_data,
						offset_, MAX_REPORT_COUNT);
			}
			global_.report_count = p_data;
			return Status::success();
		case GLOBAL_PUSH:
			if (global_stack_.size() >= MAX_GLOBAL_STACK_DEPTH) {
				return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: PUSH at byte %u nests deeper than %u", offset_,
						MAX_GLOBAL_STACK_DEPTH);
			}
			global_stack_.push_back(global_);
			return Status::success();
		case GLOBAL_POP:
			if (global_stack_.empty()) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: POP at byte %u without a matching PUSH", offset_);
			}
			global_ = global_stack_.back();
			global_stack_.pop_back();
			return Status::success();
		default:
			if (options_.strict) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: unknown global item tag 0x%X at byte %u", p_tag,
						offset_);
			}
			++out_.quirks.ignored_items;
			return Status::success();
	}
}

Status Parser::add_usage(uint32_t p_usage, uint8_t p_size) {
	// Only the first usage set of a delimited list is kept (aliases), as in Linux.
	if (local_.delimiter_branch > 1) {
		return Status::success();
	}
	if (local_.usages.size() >= MAX_LOCAL_USAGES) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: more than %u usages before the main item at byte %u",
				MAX_LOCAL_USAGES, offset_);
	}
	local_.usages.push_back(p_usage);
	local_.usage_sizes.push_back(p_size);
	return Status::success();
}

Status Parser::item_local(uint8_t p_tag, uint32_t p_data, uint32_t p_size) {
	const uint32_t full = p_size == 4 ? p_data : make_usage(global_.usage_page, static_cast<uint16_t>(p_data & 0xFFFF));
	switch (p_tag) {
		case LOCAL_USAGE:
			return add_usage(full, static_cast<uint8_t>(p_size));
		case LOCAL_USAGE_MIN:
			local_.usage_min = full;
			local_.has_usage_min = true;
			return Status::success();
		case LOCAL_USAGE_MAX: {
			if (!local_.has_usage_min) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: usage maximum at byte %u without a minimum",
						offset_);
			}
			if (usage_page_of(full) != usage_page_of(local_.usage_min) || full < local_.usage_min) {
				if (options_.strict) {
					return Status::error(StatusCode::INVALID_ARGUMENT,
							"HID descriptor: usage range 0x%08X..0x%08X at byte %u is empty or spans pages", local_.usage_min, full,
							offset_);
				}
				++out_.quirks.ignored_items;
				return Status::success();
			}
			if (full - local_.usage_min >= MAX_LOCAL_USAGES) {
				return Status::error(StatusCode::OUT_OF_RANGE, "HID descriptor: usage range at byte %u has %u usages (limit %u)",
						offset_, full - local_.usage_min + 1, MAX_LOCAL_USAGES);
			}
			for (uint32_t usage = local_.usage_min; usage <= full; ++usage) {
				// Size 4: a range is already paged and must not be re-paged.
				const Status status = add_usage(usage, 4);
				if (!status) {
					return status;
				}
			}
			return Status::success();
		}
		case LOCAL_DELIMITER:
			if (p_data == 1) {
				if (local_.delimiter_depth != 0) {
					return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: nested delimiter at byte %u", offset_);
				}
				++local_.delimiter_depth;
				++local_.delimiter_branch;
			} else if (p_data == 0) {
				if (local_.delimiter_depth == 0) {
					return Status::error(StatusCode::INVALID_ARGUMENT, "HID descriptor: delimiter close at byte %u without an open",
							offset_);
				}
				--local_.delimiter_depth;
			}
			return Status::success();
		default:
			// Designator and string indexes: nothing we use.
			return Status::success();
	}
}

void Parser::concatenate_last_usage_page() {
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

uint32_t Parser::logical_usage() const {
	for (size_t i = collection_stack_.size(); i-- > 0;) {
		const Collection &collection = out_.collections[static_cast<size_t>(collection_stack_[i])];
		if (collection.type == static_cast<uint8_t>(CollectionType::LOGICAL)) {
			return collection.usage;
		}
	}
	return 0;
}

Status Parser::add_field(ReportType p_type, uint32_t p_flags) {
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

Status Parser::open_collection(uint32_t p_type) {
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

Status Parser::close_collection() {
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

Status Parser::finish() {
	if (!collection_stack_.empty()) {
		if (options_.strict) {
			const Collection &open = out_.collections[static_cast<size_t>(collection_stack_.front())];
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"HID descriptor: %zu collection(s) still open at the end (outermost opened at byte %u)",
					collection_stack_.size(), open.byte_offset);
		}
		out_.quirks.unclosed_collections = static_cast<uint32_t>(collection_stack_.size());
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

} // namespace

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
	Parser parser(p_bytes, p_options, r_descriptor);
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
