// The extension's version (the addon's plugin.cfg, passed in by CMake).
#pragma once

#ifndef HAPTICS_VERSION
#error "HAPTICS_VERSION comes from addons/haptics/plugin.cfg through CMake"
#endif

namespace haptics::binding {

inline constexpr const char *EXTENSION_VERSION = HAPTICS_VERSION;

} // namespace haptics::binding
