#pragma once

// The movement-based renderer (force_model.h, the paper's equations): forces from the latest
// frame's contacts and the fresh input vector, the continuous sum low-pass filtered into a
// 1 kHz signal (smoothing_filter.h: the game's physics changes it in 50 Hz steps).

#include "core/renderer.h"
#include "core/smoothing_filter.h"

namespace haptics {

class MovementRenderer final : public Renderer {
public:
	void configure(const RenderConfig &p_config, double p_dt_s) override;
	void reset() override;
	void render(const RenderInput &p_input, RenderResult &r_result) override;

private:
	ForceModelConfig model_;
	SmoothingConfig smoothing_;
	double dt_s_ = 0.0; // The period the filter is designed for; 0 = not designed yet.
	SmoothingFilter filter_;
};

} // namespace haptics
