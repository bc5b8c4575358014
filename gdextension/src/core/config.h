#pragma once

// Tunable parameters of the renderers, grouped in the sections the game configures them by.
// The whole RenderConfig is validated at once (validation.h) and handed to the servo thread
// through a lock-free snapshot, so it may be changed while rendering; a rejected
// configuration leaves the previous one in force. Each field's range, unit and the key the
// game spells it with are in the field table (config_fields.h), not here.

#include "core/frame.h"
#include "pong/pong_config.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace haptics {

// How the movement renderer turns several contacts into one normal force and friction
// (force_model.h has the equations of both).
enum class ContactModel : int32_t {
	// Each contact pushes back only against the part of the input pressing into it, with its
	// own material: a floor and a wall give exactly the wall's push-back for a horizontal
	// push, and pulling away from a contact gives no force. The default, for games.
	PER_CONTACT = 0,
	// The paper's literal model: one normal, the normalised sum of the contact normals, and
	// F_n = -k p whatever the sign of p (it pulls toward a contact the input points away
	// from). For replicating the paper.
	PAPER_SUM = 1,
};
// Their names, in enum order (what set_config also accepts).
inline constexpr const char *CONTACT_MODEL_NAMES[] = { "per_contact", "paper_sum" };

struct ForceModelConfig {
	// Fraction of the workspace radius around the centre that gives no input. Outside it the
	// input is rescaled so it grows continuously from 0 at the edge.
	double dead_zone = 0.05;
	// "g" of W = m g (n.d) d. Not Earth's 9.81: it is the gain from the game's masses to felt
	// weight, and 9.81 would saturate a 3.3 N device with a 1 kg crate.
	double gravity_n_per_kg = 1.0;
	// Radius that maps to |i| = 1; 0 means the device's workspace radius.
	double input_radius_m = 0.0;
	ContactModel contact_model = ContactModel::PER_CONTACT;
	// PER_CONTACT only: a contact's friction fades in linearly while the input presses into
	// the contacts by less than this (input units), and is the paper's -b r from there on.
	// Without it friction would jump from 0 to b |r| as the hand crosses a floor's plane.
	// 0 switches friction fully on at any pressing.
	double friction_engage = 0.05;
	ContactMaterial default_contact; // For contacts with use_default_material.
	ImpactMaterial default_impact; // For impacts with use_default_material.
};

struct SmoothingConfig {
	// Off, the continuous sum goes straight through (the 50 Hz staircase is felt). On, a
	// 2nd-order Butterworth low-pass (smoothing_filter.h says why that filter).
	bool enabled = true;
	double cutoff_hz = 13.0;
};

struct SafetyConfig {
	// The player's strength preference: a gain on everything rendered, every renderer's
	// output (each component, so what the HUD shows is what is felt) and each impact's
	// amplitude before its cap. Applied before the slew limit, so changing it while
	// rendering never kicks.
	double force_scale = 1.0;
	// Output limit; 0 means the device's own limit, and a larger value is still capped by it.
	double max_force_n = 0.0;
	double max_impact_force_n = 3.0; // Cap on an impact's amplitude A(v).
	// Cap on the continuous force; 0 means the physical device's continuous rating (motors
	// overheat above it; a simulation has none). Transients may still reach the peak limit.
	double max_continuous_force_n = 0.0;
	// A physical device's session starts only once the rendered force is at most this
	// (and the device is ready): opening a device inside a wall never throws the hand.
	double start_force_n = 0.5;
	double slew_rate_n_per_s = 200.0; // How fast the continuous force may change; 0 = off.
	// Output gain ramps linearly 0 -> 1 over this time when rendering (re)starts.
	double startup_ramp_s = 0.3;
	double watchdog_timeout_s = 0.1; // No new frame for this long trips the watchdog.
	// Once tripped, the continuous force fades linearly to zero over this time, and fades
	// back in over the same time when frames return.
	double watchdog_fade_s = 0.04;
};

// 3-DOF devices (Falcon, Touch, the simulated stylus) in a 2D game: the depth axis z is held
// at the workspace centre by a spring-damper, F_z = -k z - b v_z, so the stylus moves in the
// game plane (the movement-based paper's Omni moved in its x-y plane). Planar renderers
// only (the movement and constraint renderers); 0 stiffness turns it off.
struct PlaneHoldConfig {
	double stiffness_n_per_m = 200.0;
	double damping_n_s_per_m = 1.0;
};

struct TelemetryConfig {
	uint32_t decimation = 1; // One sample every `decimation` ticks; 1 keeps every tick.
	bool enabled = true;
};

// Which renderer the servo runs (renderer.h). All of them go through the same transients and
// safety stage. Values are the renderer's index: keep them dense.
enum class RenderMode : int32_t {
	// The paper's method: acceleration control, forces from the frame's contacts.
	MOVEMENT = 0,
	// Position control against the maze's walls: a finite proxy (finite_proxy.h) in the
	// geometry set with set_constraint_geometry, F = k_c (proxy - device). The game still
	// submits a frame every physics tick (contacts may be empty): it is the watchdog's
	// heartbeat, and the clock of the FRAME_RATE proxy.
	CONSTRAINT = 1,
	// Haptic Battle Pong (core/pong_renderer.h): the ball-paddle contact closed in the servo,
	// in 3D (no plane hold). Its heartbeat for the watchdog is set_pong_input (every frame);
	// no frames are needed.
	PONG = 2,
};
inline constexpr size_t RENDER_MODE_COUNT = 3;

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

struct RenderConfig {
	ForceModelConfig force_model;
	SmoothingConfig smoothing;
	SafetyConfig safety;
	PlaneHoldConfig plane_hold;
	TelemetryConfig telemetry;
	RenderMode render_mode = RenderMode::MOVEMENT;
	ConstraintConfig constraint;
	PongConfig pong;
};

static_assert(std::is_trivially_copyable_v<RenderConfig>);

} // namespace haptics
