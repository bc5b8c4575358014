#include "renderers/vehicle/vehicle_port.h"

#include "core/wire/codec.h"

namespace haptics {

VehiclePort::VehiclePort(VehicleChannels &r_channels) :
		channels_(r_channels) {}

Status VehiclePort::set_frame(const VehicleFrame &p_frame) {
	const Status valid = check_fields(p_frame);
	if (valid) {
		channels_.frame.store(p_frame);
	}
	return valid;
}

Status VehiclePort::receive(std::span<const uint8_t> p_message) {
	return receive_one_of<VehicleFrame>(p_message, [&](const VehicleFrame &p_frame) { return set_frame(p_frame); });
}

Status VehiclePort::give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) {
	if (p_value_id != VehicleState::SCHEMA_ID) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "the vehicle renderer gives VehicleState, not layout %08x",
				unsigned(p_value_id));
	}
	r_bytes = encode(state());
	return Status::success();
}

VehicleState VehiclePort::state() const {
	return channels_.state.load();
}

} // namespace haptics
