// HapticsServer's Haptic Battle Pong methods: dictionaries in and out (pong_conversions.h),
// everything else in the Pong renderer's port (renderers/pong/pong_port.h).

#include "binding/haptics_server.h"

#include <array>

#include "binding/conversions.h"
#include "binding/log.h"
#include "binding/pong_conversions.h"
#include "renderers/pong/pong_channels.h"

namespace haptics::binding {

bool HapticsServer::set_pong_input(const gd::Dictionary &p_input) {
	PongInput input;
	std::string error;
	if (!pong_input_from_dictionary(p_input, input, error)) {
		HAPTICS_ERROR("set_pong_input: " + error + "; the previous input stays in force.");
		return false;
	}
	return report("set_pong_input", pong_.set_input(input));
}

bool HapticsServer::pong_command(const gd::Dictionary &p_command) {
	PongCommand command;
	std::string error;
	if (!pong_command_from_dictionary(p_command, command, error)) {
		HAPTICS_ERROR("pong_command: " + error + "; nothing was queued.");
		return false;
	}
	return report("pong_command", pong_.push_command(command));
}

gd::Dictionary HapticsServer::get_pong_state() const {
	return pong_state_to_dictionary(pong_.state());
}

gd::Array HapticsServer::drain_pong_events() {
	// The whole queue at most: one drain per frame empties it.
	std::array<PongEvent, PONG_EVENT_QUEUE_CAPACITY> events;
	const size_t count = pong_.drain_events(events.data(), events.size());
	gd::Array out;
	for (size_t e = 0; e < count; ++e) {
		out.append(pong_event_to_dictionary(events[e]).variant());
	}
	return out;
}

bool HapticsServer::set_hand_target_3d(gd::Vector3 p_target_m) {
	const Vec3 target{ p_target_m.x, p_target_m.y, p_target_m.z };
	if (!report("set_hand_target_3d", system_.set_hand_target(target))) {
		return false;
	}
	hand_target_ = to_game(target); // get_hand_target() stays the game-axes view of it.
	return true;
}

} // namespace haptics::binding
