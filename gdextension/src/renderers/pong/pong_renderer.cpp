#include "renderers/pong/pong_renderer.h"

#include "renderers/pong/pong_validation.h"

namespace haptics {

namespace {

// Seqlock's constructor publishes a default value: version 1 means "nothing sent yet".
constexpr uint64_t UNTOUCHED_VERSION = 1;

constexpr uint32_t FLAGS[] = { TELEMETRY_FLAG_PONG_MODE, TELEMETRY_FLAG_PADDLE_CONTACT };

} // namespace

const RendererInfo &PongRenderer::info() {
	static const RendererInfo INFO{ PONG_FORCE_NAMES, FLAGS };
	return INFO;
}

Status PongRenderer::validate(const PongConfig &p_config) {
	return validate_pong_config(p_config);
}

PongRenderer::PongRenderer(PongChannels &r_channels) :
		channels_(r_channels), inbox_(r_channels.settings) {}

void PongRenderer::pick_up_settings(double p_dt_s, bool p_restart) {
	(void)p_dt_s;
	if (inbox_.take(config_, p_restart)) {
		sim_.configure(config_);
	}
}

void PongRenderer::begin_session(double p_dt_s) {
	(void)p_dt_s;
	sim_.reset();
	input_version_ = 0; // The latest input, even one sent before this session, is taken again.
	heard_from_game_ = false;
	picked_up_ = false;
	event_drops_ = 0;
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
	forces.parts.fill(Vec3{});
	forces.parts[CONTACT_FORCE] = hand_forces.contact;
	forces.parts[SPIN_FORCE] = hand_forces.spin;
	forces.parts[EFFECTS_FORCE] = hand_forces.effects;
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

void PongRenderer::publish(const ForceComponents &p_forces, bool p_active) {
	if (!p_active && !picked_up_) {
		return;
	}
	PongState state;
	sim_.fill_state(state);
	state.events_dropped += event_drops_;
	if (p_active) {
		const auto &parts = p_forces.parts; // Scaled, as felt.
		state.hand_force = PongHandForce{ parts[CONTACT_FORCE], parts[SPIN_FORCE], parts[EFFECTS_FORCE], p_forces.total };
	}
	channels_.state.store(state);
}

} // namespace haptics
