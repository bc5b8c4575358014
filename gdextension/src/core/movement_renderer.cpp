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

RenderResult MovementRenderer::render(const RenderInput &p_input) {
	RenderResult result;
	result.forces = compute_forces(p_input.frame, p_input.input, model_);
	if (is_finite(result.forces.continuous)) {
		result.continuous = filter_.process(result.forces.continuous);
	} else {
		filter_.reset(); // Never let a NaN live on in the filter state; safety zeroes it.
		result.continuous = result.forces.continuous;
	}
	return result;
}

} // namespace haptics
