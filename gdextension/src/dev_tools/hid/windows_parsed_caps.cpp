#include "dev_tools/hid/windows_parsed_caps.h"

#include <algorithm>

namespace haptics::hid {

namespace {

struct UsageEntry {
	uint16_t page = 0;
	uint16_t min = 0;
	uint16_t max = 0;
	bool range = false;
};

struct Globals {
	uint16_t usage_page = 0;
	int32_t logical_min = 0, logical_max = 0, physical_min = 0, physical_max = 0;
	uint32_t units = 0, units_exp = 0;
	uint32_t report_size = 0, report_count = 0;
	uint8_t report_id = 0;
};

int32_t sign_extend(uint32_t p_value, uint32_t p_size) {
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

class CapsParser {
public:
	CapsParser(uint32_t p_top_level, WindowsParsedData &r_data) :
			target_(p_top_level), out_(r_data) {}

	Status run(std::span<const uint8_t> p_bytes) {
		out_ = WindowsParsedData{};
		reset_reports();
		size_t at = 0;
		while (at < p_bytes.size()) {
			const uint8_t prefix = p_bytes[at];
			if (prefix == 0xFE) { // Long item: skipped, as every parser does.
				if (at + 2 >= p_bytes.size()) {
					return Status::error(StatusCode::INVALID_ARGUMENT, "windows caps: truncated long item at byte %zu", at);
				}
				at += 3 + p_bytes[at + 1];
				continue;
			}
			const uint32_t size = (prefix & 0x03) == 3 ? 4 : (prefix & 0x03);
			if (at + 1 + size > p_bytes.size()) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "windows caps: truncated item at byte %zu", at);
			}
			uint32_t data = 0;
			for (uint32_t i = 0; i < size; ++i) {
				data |= static_cast<uint32_t>(p_bytes[at + 1 + i]) << (8 * i);
			}
			offset_ = at;
			HAPTICS_RETURN_IF_ERROR(item(prefix, data, size));
			at += 1 + size;
		}
		if (out_.collections.empty()) {
			return Status::error(StatusCode::NO_DEVICE, "windows caps: no top-level collection %u", target_);
		}
		return Status::success();
	}

	uint32_t top_levels_seen() const { return closed_top_levels_ + (stack_.empty() ? 0 : 1); }

private:
	Status item(uint8_t p_prefix, uint32_t p_data, uint32_t p_size) {
		const uint8_t type = (p_prefix >> 2) & 0x03;
		const uint8_t tag = p_prefix >> 4;
		if (type == 0) {
			return main_item(tag, p_data);
		}
		if (type == 1) {
			return global_item(tag, p_data, sign_extend(p_data, p_size));
		}
		if (type == 2) {
			return local_item(tag, p_data, p_size);
		}
		return Status::success();
	}

	Status global_item(uint8_t p_tag, uint32_t p_data, int32_t p_value) {
		switch (p_tag) {
			case 0x0:
				globals_.usage_page = static_cast<uint16_t>(p_data);
				break;
			case 0x1:
				globals_.logical_min = p_value;
				break;
			case 0x2:
				globals_.logical_max = p_value;
				break;
			case 0x3:
				globals_.physical_min = p_value;
				break;
			case 0x4:
				globals_.physical_max = p_value;
				break;
			case 0x5:
				globals_.units_exp = static_cast<uint32_t>(p_value);
				break;
			case 0x6:
				globals_.units = static_cast<uint32_t>(p_value);
				break;
			case 0x7:
				globals_.report_size = p_data;
				break;
			case 0x8:
				globals_.report_id = static_cast<uint8_t>(p_data);
				break;
			case 0x9:
				globals_.report_count = p_data;
				break;
			case 0xA:
				pushed_.push_back(globals_);
				break;
			case 0xB:
				if (pushed_.empty()) {
					return Status::error(StatusCode::INVALID_ARGUMENT, "windows caps: POP without PUSH at byte %zu", offset_);
				}
				globals_ = pushed_.back();
				pushed_.pop_back();
				break;
			default:
				break;
		}
		return Status::success();
	}

	Status local_item(uint8_t p_tag, uint32_t p_data, uint32_t p_size) {
		// A 4-byte usage carries its page; a shorter one takes the page current now.
		const uint16_t page = p_size == 4 ? static_cast<uint16_t>(p_data >> 16) : globals_.usage_page;
		const uint16_t id = static_cast<uint16_t>(p_data & 0xFFFF);
		switch (p_tag) {
			case 0x0:
				usages_.push_back(UsageEntry{ page, id, id, false });
				break;
			case 0x1:
				pending_min_ = id;
				pending_page_ = page;
				has_min_ = true;
				break;
			case 0x2:
				usages_.push_back(UsageEntry{ has_min_ ? pending_page_ : page, has_min_ ? pending_min_ : uint16_t(0), id, true });
				has_min_ = false;
				break;
			case 0xA:
				return Status::error(StatusCode::UNSUPPORTED, "windows caps: delimiter at byte %zu (not modelled)", offset_);
			default:
				break;
		}
		return Status::success();
	}

	// Items outside every collection belong to the next one (Windows splits the bytes there).
	bool in_target() const { return closed_top_levels_ == target_; }

	Status main_item(uint8_t p_tag, uint32_t p_data) {
		if (p_tag == 0xA) {
			open_collection(static_cast<uint8_t>(p_data));
		} else if (p_tag == 0xC) {
			if (stack_.empty()) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "windows caps: End Collection closes nothing at byte %zu", offset_);
			}
			stack_.pop_back();
			if (stack_.empty()) {
				++closed_top_levels_;
				reset_reports(); // Each top-level collection is parsed on its own.
			}
		} else if (p_tag == 0x8 || p_tag == 0x9 || p_tag == 0xB) {
			add_caps(p_tag == 0x8 ? 0 : (p_tag == 0x9 ? 1 : 2), static_cast<uint16_t>(p_data));
		}
		usages_.clear();
		has_min_ = false;
		return Status::success();
	}

	void open_collection(uint8_t p_type) {
		if (!in_target()) {
			stack_.push_back(0);
			return;
		}
		WindowsLinkCollection node;
		node.usage_page = usages_.empty() ? globals_.usage_page : usages_.front().page;
		node.usage = usages_.empty() ? 0 : usages_.front().min;
		node.type = p_type;
		const uint16_t index = static_cast<uint16_t>(out_.collections.size());
		if (!stack_.empty()) {
			WindowsLinkCollection &parent = out_.collections[stack_.back()];
			node.parent = stack_.back();
			node.next_sibling = parent.first_child;
			parent.first_child = index;
			++parent.child_count;
		}
		out_.collections.push_back(node);
		stack_.push_back(index);
	}

	void add_caps(uint32_t p_type, uint16_t p_bit_field) {
		uint32_t &bits = report_bits_[p_type][globals_.report_id];
		const int32_t start = static_cast<int32_t>(bits) - 8;
		bits += globals_.report_size * globals_.report_count;
		if (!in_target()) {
			return;
		}
		out_.report_byte_length[p_type] = std::max<uint16_t>(out_.report_byte_length[p_type], static_cast<uint16_t>((bits + 7) / 8));
		const bool constant = (p_bit_field & 0x01) != 0;
		const bool all_zero = std::all_of(usages_.begin(), usages_.end(), [](const UsageEntry &p_entry) {
			return !p_entry.range && p_entry.min == 0;
		});
		const bool array = (p_bit_field & 0x02) == 0;
		if (globals_.report_count == 0 || (constant && !usages_.empty() && (all_zero || array))) {
			out_.counted_caps[p_type] += static_cast<uint16_t>(std::max<size_t>(1, usages_.size()));
			return;
		}
		if (constant && usages_.empty()) {
			return;
		}
		if (usages_.empty()) {
			usages_.push_back(UsageEntry{ globals_.usage_page, 0, 0, false });
		}
		// More usages than values: the extra ones name nothing (an assumption, as Linux reads it).
		const size_t count = array ? usages_.size() : std::min<size_t>(usages_.size(), globals_.report_count);
		std::vector<WindowsCap> &caps = out_.caps[p_type];
		const size_t first = caps.size();
		caps.resize(first + count);
		int32_t end_bit = start + static_cast<int32_t>(globals_.report_size * globals_.report_count);
		for (size_t i = 0; i < count; ++i) {
			// Windows makes them last usage first; an array stores its first usage last.
			const size_t entry = array ? i : count - 1 - i;
			WindowsCap &cap = caps[first + (array ? count - 1 - i : i)];
			const uint32_t values = array ? globals_.report_count : (i == 0 ? globals_.report_count - static_cast<uint32_t>(count - 1) : 1);
			end_bit -= array ? 0 : static_cast<int32_t>(globals_.report_size * values);
			cap.first_bit = array ? start : end_bit;
			cap.report_count = static_cast<uint16_t>(values);
			cap.more_of_array = array && i > 0;
			fill_cap(usages_[entry], p_bit_field, array, cap);
			cap.data_index_min = data_indexes_[p_type];
			cap.data_index_max = static_cast<uint16_t>(cap.data_index_min + (cap.range ? cap.usage_max - cap.usage_min : 0));
			data_indexes_[p_type] = static_cast<uint16_t>(cap.data_index_max + 1);
		}
		out_.counted_caps[p_type] += static_cast<uint16_t>(count);
	}

	void fill_cap(const UsageEntry &p_usage, uint16_t p_bit_field, bool p_array, WindowsCap &r_cap) const {
		r_cap.usage_page = p_usage.page;
		r_cap.report_id = globals_.report_id;
		r_cap.bit_size = static_cast<uint16_t>(globals_.report_size);
		r_cap.bit_field = p_bit_field;
		r_cap.link_collection = stack_.empty() ? 0 : stack_.back();
		r_cap.constant = (p_bit_field & 0x01) != 0;
		r_cap.button = p_array || globals_.report_size == 1;
		r_cap.range = p_usage.range;
		r_cap.usage_min = p_usage.min;
		r_cap.usage_max = p_usage.max;
		r_cap.units = globals_.units;
		r_cap.units_exp = globals_.units_exp;
		if (p_array) {
			r_cap.null_value = static_cast<uint16_t>(globals_.logical_min);
		} else {
			r_cap.null_value = (p_bit_field & 0x40) != 0 ? 1 : 0;
		}
		if (r_cap.button) {
			r_cap.logical_min_slot = p_array ? globals_.logical_max : 0;
			return; // No logical maximum, no physical range.
		}
		r_cap.logical_min_slot = globals_.logical_min;
		r_cap.logical_max_slot = globals_.logical_max;
		r_cap.physical_min = globals_.physical_min;
		r_cap.physical_max = globals_.physical_max;
	}

	void reset_reports() {
		for (auto &bits : report_bits_) {
			bits.fill(8); // Every report starts after its ID byte, ID or not.
		}
		data_indexes_.fill(0);
	}

	uint32_t target_;
	WindowsParsedData &out_;
	size_t offset_ = 0;
	Globals globals_;
	std::vector<Globals> pushed_;
	std::vector<UsageEntry> usages_;
	uint16_t pending_min_ = 0, pending_page_ = 0;
	bool has_min_ = false;
	std::vector<uint16_t> stack_; // Open collections: node indexes (0 outside the target).
	uint32_t closed_top_levels_ = 0;
	std::array<std::array<uint32_t, 256>, WINDOWS_REPORT_TYPES> report_bits_{};
	std::array<uint16_t, WINDOWS_REPORT_TYPES> data_indexes_{};
};

} // namespace

uint32_t count_top_level_collections(std::span<const uint8_t> p_descriptor) {
	WindowsParsedData data;
	CapsParser parser(UINT32_MAX, data);
	(void)parser.run(p_descriptor);
	return parser.top_levels_seen();
}

Status parse_windows_caps(std::span<const uint8_t> p_descriptor, uint32_t p_top_level, WindowsParsedData &r_data) {
	CapsParser parser(p_top_level, r_data);
	return parser.run(p_descriptor);
}

} // namespace haptics::hid
