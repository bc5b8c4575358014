// Schema values (core/wire/codec.h) across the binding: HapticsSystem's methods take and give
// each value as the bytes of its GDScript class's encode(), so both sides are typed and the
// layout is defined once, in the value's schema. A refused value is reported through the
// engine's error printer, naming the method and the field, and changes nothing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "binding/containers.h"
#include "binding/log.h"
#include "core/wire/codec.h"

namespace haptics::binding {

inline std::span<const uint8_t> bytes_of(const gd::PackedByteArray &p_bytes) {
	return { p_bytes.ptr(), static_cast<size_t>(p_bytes.size()) };
}

gd::PackedByteArray to_packed(const std::vector<uint8_t> &p_bytes);

// False (reported as "<method>: <why>") when p_bytes hold no valid T; r_value is untouched then.
// r_space (when given) says which form a value with a 3D form came in.
template <SchemaValue T>
bool decode_argument(const char *p_method, const gd::PackedByteArray &p_bytes, T &r_value,
		GameSpace *r_space = nullptr) {
	const Status status = decode(bytes_of(p_bytes), r_value, r_space);
	if (!status) {
		gd::print_error(std::string(p_method) + ": " + status.message(), p_method, __FILE__, __LINE__);
	}
	return status.ok();
}

template <SchemaValue T>
gd::PackedByteArray encode_result(const T &p_value, GameSpace p_space = GameSpace::PLANE) {
	return to_packed(encode(p_value, p_space));
}

} // namespace haptics::binding
