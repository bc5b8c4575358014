#include "renderers/pong/pong_port.h"

#include "renderers/pong/pong_validation.h"

#include <type_traits>

namespace haptics {

PongPort::PongPort(PongChannels &r_channels) :
		channels_(r_channels) {}

Status PongPort::set_input(const PongInput &p_input) {
	const Status valid = validate_pong_input(p_input);
	if (valid) {
		PongInput input = p_input;
		for (int p = 0; p < PONG_MAX_PLAYERS; ++p) {
			if (input.players[p].normal == Vec3{}) {
				input.players[p].normal = seat_facing(p);
			}
		}
		channels_.input.store(input);
		witness_.note_paddles(channels_.state.load());
	}
	return valid;
}

Status PongPort::push_command(const PongCommand &p_command) {
	// This thread is the settings' only writer: the load never waits.
	const Status valid = validate_pong_command(p_command, channels_.settings.load());
	if (!valid) {
		return valid;
	}
	if (!channels_.commands.try_push(p_command)) {
		return Status::error(StatusCode::INVALID_STATE,
				"pong_command: %zu commands are already waiting for the servo; is it running (start or step)?",
				PONG_COMMAND_QUEUE_CAPACITY);
	}
	return Status::success();
}

Status PongPort::receive(std::span<const uint8_t> p_message) {
	return receive_one_of<PongInput, PongCommand, PongWitnessCheck, PongWitnessPose>(p_message, [&](const auto &p_value) {
		using Value = std::decay_t<decltype(p_value)>;
		if constexpr (std::is_same_v<Value, PongInput>) {
			return set_input(p_value);
		} else if constexpr (std::is_same_v<Value, PongCommand>) {
			return push_command(p_value);
		} else if constexpr (std::is_same_v<Value, PongWitnessCheck>) {
			check_ball(p_value);
			return Status::success();
		} else {
			witness_.note_pose(p_value);
			return Status::success();
		}
	});
}

Status PongPort::give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) {
	if (p_value_id == PongState::SCHEMA_ID) {
		r_bytes = encode(state());
		return Status::success();
	}
	if (p_value_id == PongEventBatch::SCHEMA_ID) {
		// The whole queue at most: one read a frame empties it.
		PongEventBatch batch;
		PongEvent event;
		while (batch.events.size() < PONG_EVENT_QUEUE_CAPACITY && channels_.events.try_pop(event)) {
			batch.events.push_back(event);
		}
		r_bytes = encode(batch);
		return Status::success();
	}
	if (p_value_id == PongWitnessVerdict::SCHEMA_ID) {
		r_bytes = encode(verdict_);
		return Status::success();
	}
	return Status::error(StatusCode::INVALID_ARGUMENT,
			"the Pong renderer gives PongState, PongEventBatch and PongWitnessVerdict, not layout %08x",
			unsigned(p_value_id));
}

const PongWitnessVerdict &PongPort::check_ball(const PongWitnessCheck &p_check) {
	const PongState latest = channels_.state.load();
	verdict_ = witness_.check(p_check, latest.time_s, channels_.settings.load(), channels_.input.load().beginner);
	return verdict_;
}

PongState PongPort::state() const {
	return channels_.state.load();
}

size_t PongPort::drain_events(PongEvent *r_out, size_t p_max) {
	if (!r_out) {
		return 0;
	}
	size_t count = 0;
	while (count < p_max && channels_.events.try_pop(r_out[count])) {
		++count;
	}
	return count;
}

} // namespace haptics
