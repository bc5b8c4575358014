#include "renderers/pong/pong_port.h"

#include "renderers/pong/pong_validation.h"

namespace haptics {

PongPort::PongPort(PongChannels &r_channels) :
		channels_(r_channels) {}

Status PongPort::set_input(const PongInput &p_input) {
	const Status valid = validate_pong_input(p_input);
	if (valid) {
		channels_.input.store(p_input);
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
