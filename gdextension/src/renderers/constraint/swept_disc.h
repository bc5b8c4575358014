#pragma once

// Continuous collision of a moving disc against a wall segment: the narrow phase of the
// finite proxy. A disc of radius r touching segment [a, b] is the disc's centre touching the
// CAPSULE around the segment (the segment inflated by r, with round caps at both ends), so
// "sweep a disc" is "cast a ray against a capsule": the earliest of the ray's entry into the
// two flat sides and into the two end circles. The round caps are what makes a convex corner
// of a polygon rounded for the proxy, and what stops it tunnelling past a segment's end.
//
// Pure functions, no allocation: they run inside the servo tick.

#include "core/base/vec2.h"

#include <type_traits>

namespace haptics {

// One wall: a line segment in maze units. Polygons are closed chains of these.
struct Segment2 {
	Vec2 a;
	Vec2 b;
};

static_assert(std::is_trivially_copyable_v<Segment2>);

struct DiscHit {
	double t = 1.0; // Fraction of the motion at first touch, [0, 1].
	Vec2 normal; // Unit, from the touched point of the segment toward the disc's centre.
};

Vec2 closest_point_on_segment(const Segment2 &p_segment, const Vec2 &p_point);

inline double distance_to_segment(const Segment2 &p_segment, const Vec2 &p_point) {
	return length(p_point - closest_point_on_segment(p_segment, p_point));
}

// Does a disc of radius p_radius centred at p_from and moving by p_motion touch the segment
// while moving toward it? Fills r_hit with the first touch and returns true, or returns false.
//
// A disc that already touches (centre within p_radius + p_touch_slack of the segment, which
// is where the proxy rests after a previous contact) hits at t = 0 if it moves toward the
// segment, and never otherwise: the distance to a convex capsule is a convex function along a
// line, so one that does not decrease at t = 0 never decreases. That is also what lets a
// disc that somehow started inside a wall leave it, but never go deeper.
// "Toward" needs an approach speed above 1e-9 |motion|: sliding exactly along a wall (which
// rounding turns into +-1e-16) is not a new contact.
bool sweep_disc_segment(const Vec2 &p_from, const Vec2 &p_motion, double p_radius, const Segment2 &p_segment,
		double p_touch_slack, DiscHit &r_hit);

} // namespace haptics
