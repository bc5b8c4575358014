#include "core/movement_renderer.h"

namespace haptics {

void MovementRenderer::configure(const RenderConfig &p_config, double p_dt_s) {
	model_ = p_config.force_model;
	// Re-designing the filter resets its state to rest (at its last output): do it only when
	// the filter itself changed, so tuning a material mid-step keeps the filter's motion.
	const SmoothingConfig &smoothing = p_config.smoothing;
	if (p_dt_s != dt_s_ || smoothing.enabled != smoothing_.enabled || smoothing.cutoff_hz != smoothing_.cutoff_hz) {
		smoothing_ = smoothing;
		dt_s_ = p_dt_s;
		filter_.configure(smoothing_, dt_s_);
	}
}

void MovementRenderer::reset() {
	filter_.reset();
}

void MovementRenderer::render(const RenderInput &p_input, RenderResult &r_result) {
	compute_forces(p_input.frame, p_input.input, model_, r_result.forces);
	r_result.flags = 0;
	if (is_finite(r_result.forces.continuous)) {
		r_result.continuous = filter_.process(r_result.forces.continuous);
	} else {
		filter_.reset(); // Never let a NaN live on in the filter state; safety zeroes it.
		r_result.continuous = r_result.forces.continuous;
	}
}

} // namespace haptics
