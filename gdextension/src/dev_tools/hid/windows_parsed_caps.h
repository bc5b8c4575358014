#pragma once

// What Windows keeps of a HID report descriptor (test support, docs/devices/hid.md, "Windows:
// the descriptor rebuilt from parsed data"). Windows gives programs only the parsed form,
// HIDP_PREPARSED_DATA, one per top-level collection; hidapi >= 0.14 rebuilds a descriptor
// from its caps (windows_rebuilt_descriptor.h). This models those caps from descriptor bytes,
// keeping what a rebuild reads:
//  - one cap per usage (or usage range) of a main item. A variable item's caps come in reverse
//    usage order, the last usage taking the values the others leave; an array's caps share its
//    bits, also in reverse, all but the first declared flagged "more of this array";
//  - bit positions count from after the report-ID byte; data indices run per report type;
//  - 1-bit variables and all arrays are button caps. A button keeps no physical range; an array
//    keeps its logical minimum in the null-value slot and its maximum in the slot a value keeps
//    its minimum in (0 in the maximum's): HIDP_BUTTON_CAPS has no logical range of its own;
//  - a constant item without usages leaves no cap; a constant array, or one whose usages are all
//    0, is counted but not stored; any other constant is a cap flagged constant (IsPadding);
//  - collections become link-collection nodes; a parent links its children newest first.
// Sources: hidapi's hid_pp_cap (windows/hidapi_descriptor_reconstruct.h) and the caps it
// captured from 25 real devices (windows/test/data/*.pp_data), Wine's dlls/hidparse.sys (which
// writes the same layout), Microsoft's HIDP_BUTTON_CAPS and HIDP_VALUE_CAPS pages.
// Values are read as Windows reads them: every item's data sign-extended from its size (so a
// one-byte Logical Maximum 0xFF is -1 there, and the rebuild writes it back as one byte).
// Not modelled (unused by the suite): delimiters (refused), string and designator indexes.

#include "core/base/status.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace haptics::hid {

inline constexpr uint32_t WINDOWS_REPORT_TYPES = 3; // HidP_Input, HidP_Output, HidP_Feature.

struct WindowsCap {
	uint16_t usage_page = 0;
	uint8_t report_id = 0;
	int32_t first_bit = 0; // From the first bit after the report-ID byte.
	uint16_t bit_size = 0;
	uint16_t report_count = 0;
	uint16_t bit_field = 0; // The main item's data.
	uint16_t link_collection = 0;
	bool more_of_array = false; // IsMultipleItemsForArray.
	bool constant = false; // IsPadding.
	bool button = false; // IsButtonCap.
	bool range = false; // usage_min..usage_max; else usage_min is the usage.
	uint16_t usage_min = 0;
	uint16_t usage_max = 0;
	uint16_t data_index_min = 0;
	uint16_t data_index_max = 0;
	// The slots as Windows fills them (see the header comment).
	uint16_t null_value = 0;
	int32_t logical_min_slot = 0;
	int32_t logical_max_slot = 0;
	int32_t physical_min = 0;
	int32_t physical_max = 0;
	uint32_t units = 0;
	uint32_t units_exp = 0;

	bool is_array() const { return (bit_field & 0x02) == 0; }
	int32_t last_bit() const { return first_bit + bit_size * report_count - 1; }
	// The logical range through the button layout (hidapi's Button.LogicalMin/Max).
	int32_t button_logical_min() const { return null_value; }
	int32_t button_logical_max() const { return logical_min_slot; }
};

struct WindowsLinkCollection {
	uint16_t usage_page = 0;
	uint16_t usage = 0;
	uint16_t parent = 0;
	uint16_t child_count = 0;
	uint16_t next_sibling = 0; // 0: none (node 0, the top-level collection, is nobody's child).
	uint16_t first_child = 0; // The child declared last.
	uint8_t type = 0;
};

struct WindowsParsedData {
	std::array<std::vector<WindowsCap>, WINDOWS_REPORT_TYPES> caps; // In Windows' order.
	std::array<uint16_t, WINDOWS_REPORT_TYPES> counted_caps{}; // NumberOfCaps: stored and empty.
	std::array<uint16_t, WINDOWS_REPORT_TYPES> report_byte_length{}; // Longest report, ID byte included.
	std::vector<WindowsLinkCollection> collections; // [0]: the top-level collection.
};

// Top-level collections in p_descriptor (Windows makes one device of each).
uint32_t count_top_level_collections(std::span<const uint8_t> p_descriptor);

// The caps Windows keeps for top-level collection p_top_level (0-based). Refuses what it does
// not model and what Windows' parser refuses (a truncated item, an End Collection that closes
// nothing), naming the byte offset.
Status parse_windows_caps(std::span<const uint8_t> p_descriptor, uint32_t p_top_level, WindowsParsedData &r_data);

} // namespace haptics::hid
