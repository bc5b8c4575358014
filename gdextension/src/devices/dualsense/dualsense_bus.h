#pragma once

// Which link the pad is on: it decides the report framing (dualsense_report.h) and rate.

#include <cstdint>

namespace haptics::dualsense {

enum class Bus : int32_t {
	UNKNOWN = 0, // Not told by the transport: inferred from the first input report.
	USB = 1,
	BLUETOOTH = 2,
};

inline const char *bus_name(Bus p_bus) {
	switch (p_bus) {
		case Bus::USB:
			return "USB";
		case Bus::BLUETOOTH:
			return "Bluetooth";
		default:
			return "unknown bus";
	}
}

} // namespace haptics::dualsense
