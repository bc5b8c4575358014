#include "renderers/constraint/swept_disc.h"

#include <algorithm>
#include <cmath>

namespace haptics {

namespace {

constexpr double APPROACH_EPSILON = 1e-9; // Relative to |motion|; see the header.

// Entry of the ray p + t d into the circle (c, r), for a ray starting outside it.
void sweep_circle(const Vec2 &p_from, const Vec2 &p_motion, const Vec2 &p_centre, double p_radius, DiscHit &r_best,
		bool &r_found) {
	const Vec2 f = p_from - p_centre;
	const double b = dot(f, p_motion);
	if (b >= 0.0) {
		return; // Moving away from (or tangent to) the circle.
	}
	const double a = length_squared(p_motion);
	const double c = length_squared(f) - p_radius * p_radius;
	const double discriminant = b * b - a * c;
	if (discriminant < 0.0) {
		return;
	}
	// The smaller root (-b - sqrt(D)) / a, written as c / (-b + sqrt(D)) so that a nearly
	// touching start (c ~ 0) does not lose its digits to cancellation.
	const double t = std::max(0.0, c / (-b + std::sqrt(discriminant)));
	if (t > 1.0 || (r_found && t >= r_best.t)) {
		return;
	}
	const Vec2 offset = f + p_motion * t;
	const double offset_length = length(offset);
	if (!(offset_length > 0.0)) {
		return;
	}
	r_best.t = t;
	r_best.normal = offset / offset_length;
	r_found = true;
}

} // namespace

Vec2 closest_point_on_segment(const Segment2 &p_segment, const Vec2 &p_point) {
	const Vec2 edge = p_segment.b - p_segment.a;
	const double edge_length_squared = length_squared(edge);
	if (!(edge_length_squared > 0.0)) {
		return p_segment.a;
	}
	const double u = std::clamp(dot(p_point - p_segment.a, edge) / edge_length_squared, 0.0, 1.0);
	return p_segment.a + edge * u;
}

bool sweep_disc_segment(const Vec2 &p_from, const Vec2 &p_motion, double p_radius, const Segment2 &p_segment,
		double p_touch_slack, DiscHit &r_hit) {
	const double motion_length = length(p_motion);
	if (!(motion_length > 0.0)) {
		return false;
	}
	const Vec2 edge = p_segment.b - p_segment.a;
	const double edge_length = length(edge);
	const Vec2 closest = closest_point_on_segment(p_segment, p_from);
	const Vec2 away = p_from - closest;
	const double distance = length(away);

	if (distance < p_radius + p_touch_slack) {
		// Touching (or inside): only motion toward the segment is stopped, right here.
		Vec2 normal;
		if (distance > 1e-12 * p_radius) {
			normal = away / distance;
		} else {
			// Centre on the segment itself: block the side the motion goes to.
			normal = perpendicular(edge) / edge_length;
			if (dot(normal, p_motion) > 0.0) {
				normal = -normal;
			}
		}
		if (dot(normal, p_motion) < -APPROACH_EPSILON * motion_length) {
			r_hit.t = 0.0;
			r_hit.normal = normal;
			return true;
		}
		return false;
	}

	DiscHit best;
	bool found = false;
	// The flat sides: the disc's centre reaches the line offset by the radius, within the
	// segment's extent.
	Vec2 side_normal = perpendicular(edge) / edge_length;
	double side_distance = dot(side_normal, p_from - p_segment.a);
	if (side_distance < 0.0) {
		side_normal = -side_normal;
		side_distance = -side_distance;
	}
	const double closing_speed = -dot(side_normal, p_motion);
	if (side_distance > p_radius && closing_speed > 0.0) {
		const double t = (side_distance - p_radius) / closing_speed;
		if (t <= 1.0) {
			const double u = dot(p_from + p_motion * t - p_segment.a, edge) / (edge_length * edge_length);
			if (u >= 0.0 && u <= 1.0) {
				best.t = t;
				best.normal = side_normal;
				found = true;
			}
		}
	}
	// The round caps. Entering the flat part through its ends means having entered a cap
	// first, so the earliest of the three entries is the capsule's.
	sweep_circle(p_from, p_motion, p_segment.a, p_radius, best, found);
	sweep_circle(p_from, p_motion, p_segment.b, p_radius, best, found);
	if (found) {
		r_hit = best;
	}
	return found;
}

} // namespace haptics
