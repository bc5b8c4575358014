#include "devices/hid/descriptor_parser.h"

namespace haptics::hid::detail {

Status DescriptorParser::run() {
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
						"HID descriptor is truncated: long item at byte %u declares %zu data bytes, %zu left", offset_, data_size,
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
					"HID descriptor is truncated: item 0x%02X at byte %u needs %u data bytes, %zu left", prefix, offset_, size,
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

Status DescriptorParser::item_main(uint8_t p_tag, uint32_t p_data) {
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

Status DescriptorParser::item_global(uint8_t p_tag, uint32_t p_data, uint32_t p_size) {
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
			// (real descriptors write `55 FD` for -3, docs/devices/hid.md), as Linux reads them.
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

Status DescriptorParser::add_usage(uint32_t p_usage, uint8_t p_size) {
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

Status DescriptorParser::item_local(uint8_t p_tag, uint32_t p_data, uint32_t p_size) {
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

} // namespace haptics::hid::detail
