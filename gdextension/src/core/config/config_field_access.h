#pragma once

// How a row of the configuration table (config_field.h) reads and writes its member of the
// owner's settings struct: HAPTICS_CONFIG_FIELD(Settings, path) gives the row's getter and
// setter of p_settings->path, converting to and from the double the table speaks (enums by
// their value, bools as 0 or 1). Only the owner's own rows file uses it.

#include <type_traits>

namespace haptics {

template <typename T>
T from_config_number(double p_value) {
	if constexpr (std::is_enum_v<T>) {
		return static_cast<T>(static_cast<std::underlying_type_t<T>>(p_value));
	} else if constexpr (std::is_same_v<T, bool>) {
		return p_value != 0.0;
	} else {
		return static_cast<T>(p_value);
	}
}

template <typename T>
double to_config_number(T p_value) {
	if constexpr (std::is_enum_v<T>) {
		return static_cast<double>(static_cast<std::underlying_type_t<T>>(p_value));
	} else {
		return static_cast<double>(p_value);
	}
}

} // namespace haptics

// The void pointers are the owner's Settings, as the engine's table hands them over.
#define HAPTICS_CONFIG_FIELD(Settings, path) \
	[](const void *p_settings) { return ::haptics::to_config_number(static_cast<const Settings *>(p_settings)->path); }, \
			[](void *p_settings, double p_value) { \
				auto &member = static_cast<Settings *>(p_settings)->path; \
				member = ::haptics::from_config_number<std::remove_reference_t<decltype(member)>>(p_value); \
			}
