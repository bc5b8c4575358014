#include "core/render/renderer_port.h"

namespace haptics {

uint32_t layout_id_of(std::span<const uint8_t> p_message) {
	if (p_message.size() < 4) {
		return 0;
	}
	return uint32_t(p_message[0]) | uint32_t(p_message[1]) << 8 | uint32_t(p_message[2]) << 16 |
			uint32_t(p_message[3]) << 24;
}

Status NoPort::receive(std::span<const uint8_t> p_message) {
	return Status::error(StatusCode::INVALID_ARGUMENT, "this renderer takes no messages of its own (layout %08x)",
			unsigned(layout_id_of(p_message)));
}

Status NoPort::give(uint32_t p_value_id, std::vector<uint8_t> &) {
	return Status::error(StatusCode::INVALID_ARGUMENT, "this renderer gives no values of its own (layout %08x)",
			unsigned(p_value_id));
}

} // namespace haptics
