#pragma once

// The game's end of the vehicle renderer. Game thread only, any time (also while another
// renderer is active: the frame waits on its channel):
//   each physics tick: port.set_frame(frame)   (in the vehicle mode, the watchdog's heartbeat)
//   any time:          port.state()
// The same through RendererPort, as the game sends them (vehicle.schema.toml): it takes
// VehicleFrame and gives VehicleState.

#include "core/base/status.h"
#include "core/render/renderer_port.h"
#include "renderers/vehicle/vehicle_channels.h"

namespace haptics {

class VehiclePort final : public RendererPort {
public:
	explicit VehiclePort(VehicleChannels &r_channels);

	Status receive(std::span<const uint8_t> p_message) override;
	Status give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) override;

	// Checked against the schema's limits (a value decoded from bytes already was: the codec
	// names the field), then published for the servo's next tick. On error the previous frame
	// stays in force.
	Status set_frame(const VehicleFrame &p_frame);
	// After the latest tick in the vehicle mode.
	VehicleState state() const;

private:
	VehicleChannels &channels_;
};

} // namespace haptics
