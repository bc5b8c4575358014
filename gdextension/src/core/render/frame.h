#pragma once

// What the game sends to the servo: one Frame per physics tick (50 Hz) and one ImpactEvent
// per collision, defined in frame.schema.toml (the structs, their limits, their GDScript
// classes). Trivially copyable with fixed-capacity arrays, so a frame reaches the servo
// thread through a lock-free snapshot without allocation; a frame or impact is valid when
// check_fields (core/wire/codec.h) accepts it.
//
// All vectors are in DEVICE space (coordinates.h: x right, y up, z toward the user); the
// codec turns the game's vectors into it (a 2D game's flipped, a 3D game's as they are).

#include "core/base/coordinates.h"
#include "core/base/vec3.h"
#include "core/render/frame.gen.h"

namespace haptics {

// Convenience for tests and benches; false (and nothing added) when the frame is full.
// A frame as the servo takes it, with the game it came from: a 3D game's frame turns off the
// plane hold of 3-DOF devices and puts a 2-axis stick on the ground plane (coordinates.h).
struct GameFrame {
	Frame frame;
	GameSpace space = GameSpace::PLANE;
};
static_assert(std::is_trivially_copyable_v<GameFrame>);

inline bool add_contact(Frame &r_frame, const Vec3 &p_normal) {
	return r_frame.contacts.push_back(Contact{ p_normal, std::nullopt });
}
inline bool add_contact(Frame &r_frame, const Vec3 &p_normal, const ContactMaterial &p_material) {
	return r_frame.contacts.push_back(Contact{ p_normal, p_material });
}
inline bool add_resting(Frame &r_frame, const Vec3 &p_normal, double p_mass_kg) {
	return r_frame.resting.push_back(RestingObject{ p_normal, p_mass_kg });
}
inline void set_water(Frame &r_frame, bool p_inside, double p_drag_n_s_per_m, double p_inertia_n) {
	r_frame.in_water = p_inside;
	r_frame.water_drag_n_s_per_m = p_drag_n_s_per_m;
	r_frame.water_inertia_n = p_inertia_n;
}

} // namespace haptics
