// The extension's version, and the release that stops accepting the keys renamed in it.
#pragma once

namespace haptics::binding {

inline constexpr const char *EXTENSION_VERSION = "0.3.0";
inline constexpr const char *OLD_KEYS_REMOVED_IN = "0.4.0";

} // namespace haptics::binding
