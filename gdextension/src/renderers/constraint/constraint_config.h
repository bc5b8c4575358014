#pragma once

// The constraint renderer's settings, section "constraint" of the game's configuration. Each
// field's range, unit and key are in its row of the field table (constraint_config_fields.cpp).

#include <cstdint>
#include <type_traits>

namespace haptics {

enum class ProxyUpdate : int32_t {
	SERVO_RATE = 0, // The proxy moves every servo tick (1 kHz): the product.
	// The proxy moves only on ticks that pick up a new frame (50 Hz), as in the paper's
	// study; between frames it is held and the force still follows the device at the servo
	// rate.
	FRAME_RATE = 1,
};
// Their names, in enum order (what set_config also accepts).
inline constexpr const char *PROXY_UPDATE_NAMES[] = { "servo", "frame" };

struct ConstraintConfig {
	// k_c. Keep it at or below the device's max_stiffness_n_per_m (the force is clamped by
	// the safety stage either way).
	double stiffness_n_per_m = 300.0;
	// Radius of the proxy disc in MAZE units (the avatar's collision radius). Changing it
	// re-places the proxy (see FiniteProxy::reset).
	double proxy_radius = 8.0;
	ProxyUpdate update = ProxyUpdate::SERVO_RATE;
	uint32_t max_iterations = 6; // Sweeps per proxy update: a corner needs 2-3, a dead end 3-4.
};

static_assert(std::is_trivially_copyable_v<ConstraintConfig>);

} // namespace haptics
