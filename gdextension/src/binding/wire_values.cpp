#include "binding/wire_values.h"

#include <cstring>

namespace haptics::binding {

gd::PackedByteArray to_packed(const std::vector<uint8_t> &p_bytes) {
	gd::PackedByteArray out;
	if (!p_bytes.empty() && out.resize(static_cast<int64_t>(p_bytes.size()))) {
		std::memcpy(out.ptrw(), p_bytes.data(), p_bytes.size());
	}
	return out;
}

} // namespace haptics::binding
