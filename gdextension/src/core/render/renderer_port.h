#pragma once

// What a renderer offers the game beyond what every renderer takes (frames, impacts, its
// settings): values of its own schema, in and out, told apart by their layout id (the
// first four bytes of an encoding, core/wire/codec.h). The binding hands these bytes through
// untouched (HapticsSystem.renderer_send / renderer_read), so a renderer's messages are
// defined in its folder alone. Game thread only.

#include "core/base/status.h"
#include "core/wire/codec.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace haptics {

class RendererPort {
public:
	virtual ~RendererPort() = default;

	// Acts on p_message, a value of this renderer's schema that it takes; anything else is
	// refused by name and changes nothing.
	virtual Status receive(std::span<const uint8_t> p_message) = 0;
	// The value of layout p_value_id this renderer gives (a snapshot, or what it queued since
	// the last read), encoded into r_bytes; an id it does not give is an error.
	virtual Status give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) = 0;
};

// A renderer that takes and gives nothing of its own (the movement renderer: frames and
// impacts are every renderer's).
class NoPort final : public RendererPort {
public:
	template <typename Channels>
	explicit NoPort(Channels &) {}

	Status receive(std::span<const uint8_t> p_message) override;
	Status give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) override;
};

// The layout id p_message starts with (0 when it is shorter than one).
uint32_t layout_id_of(std::span<const uint8_t> p_message);

// Decodes p_message as whichever of Values its layout id names and hands it to p_handler
// (one overload a value); a layout none of them has is refused, naming them.
template <SchemaValue... Values, typename Handler>
Status receive_one_of(std::span<const uint8_t> p_message, Handler &&p_handler) {
	const uint32_t id = layout_id_of(p_message);
	bool matched = false;
	Status status;
	const auto try_one = [&]<typename V>(V *) {
		if (!matched && id == V::SCHEMA_ID) {
			matched = true;
			V value{};
			status = decode(p_message, value);
			if (status) {
				status = p_handler(value);
			}
		}
	};
	(try_one(static_cast<Values *>(nullptr)), ...);
	if (!matched) {
		const std::string names = ((std::string(Values::NAME) + ", ") + ...);
		return Status::error(StatusCode::INVALID_ARGUMENT, "layout %08x is none of the values this renderer takes (%s)",
				unsigned(id), names.substr(0, names.size() - 2).c_str());
	}
	return status;
}

} // namespace haptics
