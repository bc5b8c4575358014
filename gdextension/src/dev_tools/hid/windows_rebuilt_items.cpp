// The last step of the Windows descriptor rebuild: hidapi's encoder, writing the list of main
// items (windows_rebuilt_list.h) as short items.

#include "dev_tools/hid/windows_rebuilt_list.h"

namespace haptics::hid::windows_rebuild {

namespace {

enum : uint8_t {
	ITEM_INPUT = 0x80,
	ITEM_OUTPUT = 0x90,
	ITEM_FEATURE = 0xB0,
	ITEM_COLLECTION = 0xA0,
	ITEM_END_COLLECTION = 0xC0,
	ITEM_USAGE_PAGE = 0x04,
	ITEM_LOGICAL_MIN = 0x14,
	ITEM_LOGICAL_MAX = 0x24,
	ITEM_PHYSICAL_MIN = 0x34,
	ITEM_PHYSICAL_MAX = 0x44,
	ITEM_UNIT_EXPONENT = 0x54,
	ITEM_UNIT = 0x64,
	ITEM_REPORT_SIZE = 0x74,
	ITEM_REPORT_ID = 0x84,
	ITEM_REPORT_COUNT = 0x94,
	ITEM_USAGE = 0x08,
	ITEM_USAGE_MIN = 0x18,
	ITEM_USAGE_MAX = 0x28,
};

constexpr uint8_t MAIN_ITEMS[WINDOWS_REPORT_TYPES] = { ITEM_INPUT, ITEM_OUTPUT, ITEM_FEATURE };

class Writer {
public:
	explicit Writer(std::vector<uint8_t> &r_bytes) :
			bytes_(r_bytes) {}

	// Logical and physical limits: the shortest signed form; out of 32 bits, nothing (as hidapi).
	void signed_item(uint8_t p_prefix, int64_t p_value) {
		if (p_value >= -128 && p_value <= 127) {
			put(p_prefix, static_cast<uint32_t>(p_value), 1);
		} else if (p_value >= -32768 && p_value <= 32767) {
			put(p_prefix, static_cast<uint32_t>(p_value), 2);
		} else if (p_value >= INT32_MIN && p_value <= INT32_MAX) {
			put(p_prefix, static_cast<uint32_t>(p_value), 4);
		}
	}
	// Every other item: the shortest unsigned form; a negative value writes nothing.
	void unsigned_item(uint8_t p_prefix, int64_t p_value) {
		if (p_value < 0 || p_value > UINT32_MAX) {
			return;
		}
		put(p_prefix, static_cast<uint32_t>(p_value), p_value <= 0xFF ? 1 : (p_value <= 0xFFFF ? 2 : 4));
	}
	void end_collection() { bytes_.push_back(ITEM_END_COLLECTION); }

private:
	void put(uint8_t p_prefix, uint32_t p_value, uint32_t p_size) {
		bytes_.push_back(static_cast<uint8_t>(p_prefix | (p_size == 4 ? 3 : p_size)));
		for (uint32_t i = 0; i < p_size; ++i) {
			bytes_.push_back(static_cast<uint8_t>(p_value >> (8 * i)));
		}
	}

	std::vector<uint8_t> &bytes_;
};

// The globals hidapi remembers between items.
struct Written {
	uint8_t report_id = 0;
	uint16_t usage_page = 0;
	int32_t physical_min = 0, physical_max = 0;
	uint32_t units_exp = 0, units = 0;
	int32_t merged = 0; // Caps folded into the next main item's Report Count.
};

class Encoder {
public:
	Encoder(const WindowsParsedData &p_data, const MainItemList &p_list, const WindowsRebuildOptions &p_options,
			std::vector<uint8_t> &r_bytes) :
			data_(p_data), list_(p_list), options_(p_options), out_(r_bytes) {
		for (uint32_t type = 0; type < WINDOWS_REPORT_TYPES; ++type) {
			for (const WindowsCap &cap : p_data.caps[type]) {
				counts_[type].push_back(cap.report_count);
			}
		}
	}

	void run() {
		for (int32_t at = list_.head; at >= 0; at = list_.at(at).next) {
			const Node &node = list_.at(at);
			if (node.main == NODE_COLLECTION) {
				const WindowsLinkCollection &collection = data_.collections[node.collection];
				usage_page(collection.usage_page);
				out_.unsigned_item(ITEM_USAGE, collection.usage);
				out_.unsigned_item(ITEM_COLLECTION, collection.type);
			} else if (node.main == NODE_END_COLLECTION) {
				out_.end_collection();
			} else if (node.kind == NodeKind::PADDING) {
				write_padding(node);
			} else if (cap(node).button) {
				write_button(node);
			} else {
				write_value(node);
			}
		}
	}

private:
	const WindowsCap &cap(const Node &p_node) const { return data_.caps[p_node.main][static_cast<size_t>(p_node.cap)]; }
	uint16_t &count(const Node &p_node) { return counts_[p_node.main][static_cast<size_t>(p_node.cap)]; }
	const Node *next_cap(const Node &p_node) const {
		if (p_node.next < 0) {
			return nullptr;
		}
		const Node &next = list_.at(p_node.next);
		return next.main == p_node.main && next.kind == NodeKind::CAP ? &next : nullptr;
	}

	void usage_page(uint16_t p_page) {
		if (p_page != written_.usage_page) {
			out_.unsigned_item(ITEM_USAGE_PAGE, p_page);
			written_.usage_page = p_page;
		}
	}

	void cap_locals(const WindowsCap &p_cap) {
		if (p_cap.report_id != written_.report_id) {
			out_.unsigned_item(ITEM_REPORT_ID, p_cap.report_id);
			written_.report_id = p_cap.report_id;
		}
		usage_page(p_cap.usage_page);
		if (p_cap.range) {
			out_.unsigned_item(ITEM_USAGE_MIN, p_cap.usage_min);
			out_.unsigned_item(ITEM_USAGE_MAX, p_cap.usage_max);
		} else {
			out_.unsigned_item(ITEM_USAGE, p_cap.usage_min);
		}
	}

	// hidapi writes padding as whole bytes or as one value of the gap's width, Constant.
	void write_padding(const Node &p_node) {
		const int32_t bits = p_node.last_bit - p_node.first_bit + 1;
		out_.unsigned_item(ITEM_REPORT_SIZE, bits % 8 == 0 ? 8 : bits);
		out_.unsigned_item(ITEM_REPORT_COUNT, bits % 8 == 0 ? bits / 8 : 1);
		out_.unsigned_item(MAIN_ITEMS[p_node.main], 0x03);
		written_.merged = 0;
	}

	void write_button(const Node &p_node) {
		const WindowsCap &button = cap(p_node);
		cap_locals(button);
		// Single-usage buttons of one report and kind share a main item; an array's usages
		// (same first bit) add no value.
		const Node *next = next_cap(p_node);
		if (next && cap(*next).button && !button.range && !cap(*next).range && cap(*next).usage_page == button.usage_page &&
				cap(*next).report_id == button.report_id && cap(*next).bit_field == button.bit_field) {
			written_.merged += next->first_bit != p_node.first_bit ? 1 : 0;
			return;
		}
		int64_t minimum = button.button_logical_min();
		int64_t maximum = button.button_logical_max();
		if (button.is_array() && options_.array_range == WindowsArrayRange::VALUE_SLOTS) {
			minimum = button.logical_min_slot;
			maximum = button.logical_max_slot;
		}
		if (minimum == 0 && maximum == 0) { // A plain button keeps no range: hidapi writes 0..1.
			maximum = 1;
		}
		out_.signed_item(ITEM_LOGICAL_MIN, minimum);
		out_.signed_item(ITEM_LOGICAL_MAX, maximum);
		out_.unsigned_item(ITEM_REPORT_SIZE, button.bit_size);
		out_.unsigned_item(ITEM_REPORT_COUNT, button.range ? button.report_count : button.report_count + written_.merged);
		// A button has no physical range nor unit: back to none where one was written.
		if (written_.physical_min != 0) {
			out_.signed_item(ITEM_PHYSICAL_MIN, 0);
		}
		if (written_.physical_max != 0) {
			out_.signed_item(ITEM_PHYSICAL_MAX, 0);
		}
		if (written_.units_exp != 0) {
			out_.unsigned_item(ITEM_UNIT_EXPONENT, 0);
		}
		if (written_.units != 0) {
			out_.unsigned_item(ITEM_UNIT, 0);
		}
		written_.physical_min = written_.physical_max = 0;
		written_.units_exp = written_.units = 0;
		out_.unsigned_item(MAIN_ITEMS[p_node.main], button.bit_field);
		written_.merged = 0;
	}

	void write_value(const Node &p_node) {
		const WindowsCap &value = cap(p_node);
		cap_locals(value);
		if (value.is_array()) {
			count(p_node) = static_cast<uint16_t>(value.data_index_max - value.data_index_min + 1);
		}
		// Single-usage values of equal globals, one value each, share a main item.
		const Node *next = next_cap(p_node);
		if (next && !cap(*next).button && !value.range && !cap(*next).range && same_globals(value, cap(*next)) &&
				count(*next) == 1 && count(p_node) == 1) {
			++written_.merged;
			return;
		}
		out_.signed_item(ITEM_LOGICAL_MIN, value.logical_min_slot);
		out_.signed_item(ITEM_LOGICAL_MAX, value.logical_max_slot);
		if (written_.physical_min != value.physical_min || written_.physical_max != value.physical_max) {
			out_.signed_item(ITEM_PHYSICAL_MIN, value.physical_min);
			out_.signed_item(ITEM_PHYSICAL_MAX, value.physical_max);
			written_.physical_min = value.physical_min;
			written_.physical_max = value.physical_max;
		}
		if (written_.units_exp != value.units_exp) {
			out_.unsigned_item(ITEM_UNIT_EXPONENT, value.units_exp);
			written_.units_exp = value.units_exp;
		}
		if (written_.units != value.units) {
			out_.unsigned_item(ITEM_UNIT, value.units);
			written_.units = value.units;
		}
		out_.unsigned_item(ITEM_REPORT_SIZE, value.bit_size);
		out_.unsigned_item(ITEM_REPORT_COUNT, count(p_node) + written_.merged);
		out_.unsigned_item(MAIN_ITEMS[p_node.main], value.bit_field);
		written_.merged = 0;
	}

	static bool same_globals(const WindowsCap &p_a, const WindowsCap &p_b) {
		return p_a.usage_page == p_b.usage_page && p_a.logical_min_slot == p_b.logical_min_slot &&
				p_a.logical_max_slot == p_b.logical_max_slot && p_a.physical_min == p_b.physical_min &&
				p_a.physical_max == p_b.physical_max && p_a.units_exp == p_b.units_exp && p_a.units == p_b.units &&
				p_a.bit_size == p_b.bit_size && p_a.report_id == p_b.report_id && p_a.bit_field == p_b.bit_field;
	}

	const WindowsParsedData &data_;
	const MainItemList &list_;
	WindowsRebuildOptions options_;
	Writer out_;
	Written written_;
	// Report Counts as the encoder sees them: hidapi rewrites a value array's to its usage count.
	std::array<std::vector<uint16_t>, WINDOWS_REPORT_TYPES> counts_;
};

} // namespace

std::vector<uint8_t> encode_main_items(const WindowsParsedData &p_data, const MainItemList &p_list,
		const WindowsRebuildOptions &p_options) {
	std::vector<uint8_t> bytes;
	Encoder(p_data, p_list, p_options, bytes).run();
	return bytes;
}

} // namespace haptics::hid::windows_rebuild
