#pragma once

// A HID report descriptor as hidapi >= 0.14 rebuilds it on Windows (test support, docs/devices/
// hid.md, "Windows: the descriptor rebuilt from parsed data"), from the caps Windows keeps
// (windows_parsed_caps.h), so the suite can check that what our parser and the PID layout find
// there is what they find in the original. The steps follow hidapi's
// windows/hidapi_descriptor_reconstruct.c (read, not copied):
//  - each collection's bit span per report, from its own caps, then merged into its parent the
//    way hidapi does it: the sibling chain advances at every (report ID, report type) step and a
//    parent without caps of its own keeps no first bit, so such a parent counts as "before";
//  - children ordered by first bit, caps placed between them by bit position;
//  - the gaps and the tails of reports filled with constant padding (whole bytes, else one
//    value of the gap's width), and, without report IDs, each type padded to its length;
//  - items written with a usage page only when it changes, consecutive caps merged into one
//    main item where their globals agree, physical range and units written only when changed.
// Checked offline against hidapi's 25 pairs of real and rebuilt descriptors: 24 come out byte for
// byte (docs/devices/hid.md says where the 25th differs).

#include "dev_tools/hid/windows_parsed_caps.h"

#include <cstdint>
#include <span>
#include <vector>

namespace haptics::hid {

// How the rebuild reads an array's logical range from its button cap.
enum class WindowsArrayRange : uint8_t {
	// hidapi: through the button layout, the range as declared (so its 25 devices show).
	BUTTON_SLOTS = 0,
	// Through the slots a value cap uses: the array's maximum as its minimum and 0 as its maximum,
	// the "12..0" a SideWinder Force Feedback 2 (045e:001b) showed rebuilt on Windows (issue 38).
	VALUE_SLOTS = 1,
};

struct WindowsRebuildOptions {
	WindowsArrayRange array_range = WindowsArrayRange::BUTTON_SLOTS;
};

// The descriptor hidapi's hid_get_report_descriptor returns for p_data.
std::vector<uint8_t> rebuild_windows_descriptor(const WindowsParsedData &p_data, const WindowsRebuildOptions &p_options);

// The same from descriptor bytes: their top-level collection p_top_level as Windows parses it.
Status windows_rebuilt_descriptor(std::span<const uint8_t> p_descriptor, uint32_t p_top_level,
		const WindowsRebuildOptions &p_options, std::vector<uint8_t> &r_bytes);

} // namespace haptics::hid
