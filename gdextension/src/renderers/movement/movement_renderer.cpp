#include "renderers/movement/movement_renderer.h"

#include "renderers/movement/force_model.h"

namespace haptics {

const RendererInfo &MovementRenderer::info() {
	static const RendererInfo INFO{ MOVEMENT_FORCE_NAMES, {} };
	return INFO;
}

MovementRenderer::MovementRenderer(MovementChannels &r_channels) :
		inbox_(r_channels.settings) {}

void MovementRenderer::pick_up_settings(double p_dt_s, bool p_restart) {
	if (!inbox_.take(config_, p_restart) && p_dt_s == dt_s_) {
		return;
	}
	// Re-designing the filter resets its state to rest (at its last output): do it only when
	// the filter itself changed, so tuning a material mid-step keeps the filter's motion.
	const SmoothingConfig &smoothing = config_.smoothing;
	if (p_dt_s != dt_s_ || smoothing.enabled != designed_.enabled || smoothing.cutoff_hz != designed_.cutoff_hz) {
		designed_ = smoothing;
		dt_s_ = p_dt_s;
		filter_.configure(designed_, dt_s_);
	}
}

void MovementRenderer::reset() {
	filter_.reset();
}

void MovementRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	compute_forces(p_input.frame, p_input.input, config_.force_model, r_result.forces);
	r_result.flags = 0;
	if (is_finite(r_result.forces.continuous)) {
		r_result.continuous = filter_.process(r_result.forces.continuous);
	} else {
		filter_.reset(); // Never let a NaN live on in the filter state; safety zeroes it.
		r_result.continuous = r_result.forces.continuous;
	}
}

} // namespace haptics
