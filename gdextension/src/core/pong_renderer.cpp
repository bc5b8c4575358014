#include "core/pong_renderer.h"

#include "core/servo_output.h"
#include "core/telemetry.h"

namespace haptics {

namespace {

// Seqlock's constructor publishes a default value: version 1 means "nothing sent yet".
constexpr uint64_t UNTOUCHED_VERSION = 1;

} // namespace

PongRenderer::PongRenderer(PongChannels &r_channels) :
		channels_(r_channels) {}

void PongRenderer::begin_session(double p_dt_s) {
	(void)p_dt_s;
	sim_.reset();
	input_version_ = 0; // The latest input, even one sent before this session, is taken again.
	heard_from_game_ = false;
	picked_up_ = false;
	event_drops_ = 0;
}

void PongRenderer::configure(const RenderConfig &p_config, double p_dt_s) {
	(void)p_dt_s;
	sim_.configure(p_config.pong);
}

void PongRenderer::reset() {
	sim_.settle();
}

void PongRenderer::pick_up() {
	heard_from_game_ = false;
	picked_up_ = false;
	// The seqlock's own default is not the game's: until it sends one, the sim keeps its
	// no-paddles input.
	const uint64_t latest = channels_.input.version();
	if (latest != input_version_ && latest > UNTOUCHED_VERSION) {
		PongInput input;
		uint64_t version = 0;
		if (channels_.input.try_load(input, &version)) {
			input_version_ = version;
			sim_.set_input(input);
			heard_from_game_ = true;
			picked_up_ = true;
		}
	}
	// Bounded by the queue's capacity.
	PongCommand command;
	while (channels_.commands.try_pop(command)) {
		sim_.apply(command);
		picked_up_ = true;
	}
}

void PongRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	const DeviceState &device = p_input.device;
	const HandSample hand{ device.position_m, device.velocity_m_per_s, device.orientation, p_input.has_orientation };
	sim_.step(p_input.dt_s, &hand);

	const HandForces &hand_forces = sim_.hand_forces();
	ForceComponents &forces = r_result.forces;
	forces.normal = hand_forces.contact;
	forces.friction = hand_forces.spin;
	forces.weight = hand_forces.effects;
	forces.drag = Vec3{};
	forces.inertia = Vec3{};
	forces.continuous = hand_forces.contact + hand_forces.spin + hand_forces.effects;
	r_result.continuous = forces.continuous; // Not filtered: see the header.
	const int player = sim_.device_player();
	const bool touching = player >= 0 && sim_.contact(player).touching;
	r_result.flags = TELEMETRY_FLAG_PONG_MODE | (touching ? TELEMETRY_FLAG_PADDLE_CONTACT : 0u);

	PongEvent event;
	while (sim_.events().pop(event)) {
		if (!channels_.events.try_push(event)) {
			++event_drops_;
		}
	}
}

void PongRenderer::publish(ServoOutput &r_output, bool p_active) const {
	if (!p_active && !picked_up_) {
		return;
	}
	PongState state;
	sim_.fill_state(state);
	state.events_dropped += event_drops_;
	if (p_active) {
		const ForceComponents &forces = r_output.forces; // Scaled, as felt.
		state.hand_force = PongHandForce{ forces.normal, forces.friction, forces.weight, forces.total };
	}
	channels_.state.store(state);
}

} // namespace haptics
