// The extension's version (the addon's plugin.cfg, passed in by CMake), and the release that
// stops accepting the keys renamed in it.
#pragma once

#ifndef HAPTICS_VERSION
#error "HAPTICS_VERSION comes from addons/haptics/plugin.cfg through CMake"
#endif

namespace haptics::binding {

inline constexpr const char *EXTENSION_VERSION = HAPTICS_VERSION;
inline constexpr const char *OLD_KEYS_REMOVED_IN = "0.4.0";

} // namespace haptics::binding
