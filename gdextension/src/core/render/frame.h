#pragma once

// What the game sends to the servo: one Frame per physics tick (50 Hz) and one ImpactEvent
// per collision. Plain, trivially copyable structs with fixed-capacity arrays, so a frame
// can be handed to the servo thread by a lock-free snapshot without allocation.
//
// All vectors are in DEVICE space (see coordinates.h: x right, y up, z toward the user);
// the binding converts game vectors with game_to_device_direction / game_to_device_scaled.

#include "core/base/vec3.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace haptics {

inline constexpr size_t MAX_CONTACTS = 16;
inline constexpr size_t MAX_RESTING_OBJECTS = 8;

// Upper bound of every gain the game may send (k and b in N per unit input, impact gains in
// N per m/s, water drag in N per m/s, water inertia in N).
inline constexpr double MAX_GAIN = 100.0;
inline constexpr double MIN_IMPACT_FREQUENCY_HZ = 1.0;
inline constexpr double MAX_IMPACT_FREQUENCY_HZ = 1000.0;
inline constexpr double MIN_IMPACT_DECAY_S = 0.001;
inline constexpr double MAX_IMPACT_DECAY_S = 1.0;

// Movement-based gains act on the dimensionless input vector, so they are in newtons per
// unit input: k = 2 means pushing the stylus to the edge of the workspace straight into a
// wall is resisted with 2 N.
struct ContactMaterial {
	double stiffness = 2.0; // k, N per unit input, [0, MAX_GAIN].
	double friction = 1.0; // b, N per unit input, [0, MAX_GAIN].
};

// An impact is rendered as A(v) e^(-t/decay) sin(2 pi frequency t) with A(v) = gain * speed,
// capped by SafetyConfig::max_impact_force.
struct ImpactMaterial {
	double gain = 0.5; // N per (m/s) of impact speed, [0, MAX_GAIN].
	// [MIN_IMPACT_FREQUENCY_HZ, MAX_IMPACT_FREQUENCY_HZ]; vibrotactile sensitivity peaks
	// near 200-300 Hz.
	double frequency_hz = 150.0;
	double decay_s = 0.03; // Time constant tau, [MIN_IMPACT_DECAY_S, MAX_IMPACT_DECAY_S].
};

struct Contact {
	// From the touched surface toward the player (KinematicCollision2D.get_normal()).
	// Any finite non-zero length; the force model normalises it.
	Vec3 normal;
	ContactMaterial material;
	// When true, `material` is ignored and the engine's default contact material is used.
	bool use_default_material = true;
};

// A dynamic object lying on the player. Its weight is felt only when its contact normal has
// a downward component (n.d > 0): a crate on top of the player pushes down; one the player
// stands on (n points up) or touches from the side (n horizontal) does not.
struct RestingObject {
	Vec3 normal; // From the object toward the player; finite, non-zero.
	double mass = 0.0; // kg, [0, 1000].
};

struct WaterState {
	bool inside = false;
	double drag = 0.0; // c in F = -c v, N per (m/s), [0, MAX_GAIN].
	double inertia = 0.0; // w in F = w d (d = down), N, [-MAX_GAIN, MAX_GAIN]; negative = buoyancy.
};

struct Frame {
	uint64_t sequence = 0; // The game's own counter; informational (telemetry, debugging).
	double timestamp_s = 0.0; // Game time; informational. The watchdog uses servo time.
	uint32_t contact_count = 0; // <= MAX_CONTACTS.
	Contact contacts[MAX_CONTACTS] = {};
	uint32_t resting_count = 0; // <= MAX_RESTING_OBJECTS.
	RestingObject resting[MAX_RESTING_OBJECTS] = {};
	WaterState water;
	Vec3 player_velocity; // m/s, device space, |v| <= 1000.

	// Convenience for tests and the binding; false when full.
	bool add_contact(const Vec3 &p_normal) {
		if (contact_count >= MAX_CONTACTS) {
			return false;
		}
		contacts[contact_count++] = Contact{ p_normal, ContactMaterial{}, true };
		return true;
	}
	bool add_contact(const Vec3 &p_normal, const ContactMaterial &p_material) {
		if (contact_count >= MAX_CONTACTS) {
			return false;
		}
		contacts[contact_count++] = Contact{ p_normal, p_material, false };
		return true;
	}
	bool add_resting(const Vec3 &p_normal, double p_mass) {
		if (resting_count >= MAX_RESTING_OBJECTS) {
			return false;
		}
		resting[resting_count++] = RestingObject{ p_normal, p_mass };
		return true;
	}
};

struct ImpactEvent {
	Vec3 direction; // Direction of the felt push, usually the contact normal; non-zero.
	double speed = 0.0; // m/s along the normal at impact, [0, 1000].
	ImpactMaterial material;
	bool use_default_material = true;
};

static_assert(std::is_trivially_copyable_v<Frame>);
static_assert(std::is_trivially_copyable_v<ImpactEvent>);

} // namespace haptics
