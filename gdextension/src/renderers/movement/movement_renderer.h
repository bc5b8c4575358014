#pragma once

// The movement-based renderer (force_model.h, the paper's equations): forces from the latest
// frame's contacts and the fresh input vector, the continuous sum low-pass filtered into a
// 1 kHz signal (smoothing_filter.h: the game's physics changes it in 50 Hz steps). Its
// components are named normal, friction, weight, drag and inertia (MovementForce).

#include "core/base/seqlock.h"
#include "core/render/renderer.h"
#include "core/render/renderer_channels.h"
#include "core/render/renderer_info.h"
#include "core/render/renderer_port.h"
#include "core/render/settings_inbox.h"
#include "renderers/movement/movement_config.h"
#include "renderers/movement/smoothing_filter.h"

#include <span>

namespace haptics {

struct MovementChannels : RendererChannels {
	Seqlock<MovementConfig> settings; // Game -> servo.
};

class MovementRenderer final : public Renderer {
public:
	using Config = MovementConfig;
	using Channels = MovementChannels;
	using Port = NoPort;
	static const RendererInfo &info();

	explicit MovementRenderer(MovementChannels &r_channels);

	void pick_up_settings(double p_dt_s, bool p_restart) override;
	void reset() override;
	void render(const RenderInput &p_input, RenderResult &r_result) override;

private:
	SettingsInbox<MovementConfig> inbox_;
	MovementConfig config_;
	double dt_s_ = 0.0; // The period the filter is designed for; 0 = not designed yet.
	SmoothingConfig designed_; // The smoothing the filter is designed for.
	SmoothingFilter filter_;
};

} // namespace haptics
