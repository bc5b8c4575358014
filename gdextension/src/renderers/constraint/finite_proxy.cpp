#include "renderers/constraint/finite_proxy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace haptics {

namespace {

// Motions shorter than this fraction of the radius are not worth a sweep.
constexpr double MIN_RELATIVE_MOTION = 1e-12;
// Constraint feasibility tolerance and "same wall" test, relative to the radius / unit.
constexpr double RELATIVE_TOLERANCE = 1e-9;
constexpr double SAME_NORMAL = 1.0 - 1e-12;
constexpr double PARALLEL = 1e-9; // |sin| between two normals below which no corner exists.

bool satisfies_all(const Vec2 &p_point, const ProxyConstraint *p_constraints, uint32_t p_count, double p_tolerance) {
	for (uint32_t c = 0; c < p_count; ++c) {
		if (dot(p_constraints[c].normal, p_point) < p_constraints[c].offset - p_tolerance) {
			return false;
		}
	}
	return true;
}

// Clips the motion p_from + t p_motion, t in [r_begin, r_end], to the box (slab test);
// false when it misses the box.
bool clip_to_box(const Vec2 &p_from, const Vec2 &p_motion, const Vec2 &p_low, const Vec2 &p_high, double &r_begin,
		double &r_end) {
	const double from[2] = { p_from.x, p_from.y };
	const double motion[2] = { p_motion.x, p_motion.y };
	const double low[2] = { p_low.x, p_low.y };
	const double high[2] = { p_high.x, p_high.y };
	for (int axis = 0; axis < 2; ++axis) {
		if (motion[axis] == 0.0) {
			if (from[axis] < low[axis] || from[axis] > high[axis]) {
				return false;
			}
			continue;
		}
		double enter = (low[axis] - from[axis]) / motion[axis];
		double leave = (high[axis] - from[axis]) / motion[axis];
		if (enter > leave) {
			std::swap(enter, leave);
		}
		r_begin = std::max(r_begin, enter);
		r_end = std::min(r_end, leave);
	}
	return r_begin <= r_end;
}

} // namespace

bool disc_fits(const ConstraintGeometry &p_geometry, const Vec2 &p_centre, double p_radius) {
	bool fits = true;
	p_geometry.for_each_near(p_centre, p_centre, p_radius * (1.0 + 2.0 * PROXY_SKIN), [&](size_t p_index) {
		if (fits && distance_to_segment(p_geometry.segment(p_index), p_centre) < p_radius) {
			fits = false;
		}
	});
	return fits;
}

Vec2 project_onto_constraints(const Vec2 &p_goal, const ProxyConstraint *p_constraints, uint32_t p_count,
		const Vec2 &p_fallback, double p_tolerance) {
	if (satisfies_all(p_goal, p_constraints, p_count, p_tolerance)) {
		return p_goal;
	}
	Vec2 best = p_fallback;
	double best_distance = length_squared(p_fallback - p_goal);
	const auto consider = [&](const Vec2 &p_candidate) {
		const double distance = length_squared(p_candidate - p_goal);
		if (distance < best_distance && satisfies_all(p_candidate, p_constraints, p_count, p_tolerance)) {
			best = p_candidate;
			best_distance = distance;
		}
	};
	for (uint32_t i = 0; i < p_count; ++i) {
		const ProxyConstraint &a = p_constraints[i];
		consider(p_goal + a.normal * (a.offset - dot(a.normal, p_goal))); // On line i.
		for (uint32_t j = i + 1; j < p_count; ++j) {
			const ProxyConstraint &b = p_constraints[j];
			const double determinant = cross(a.normal, b.normal);
			if (std::abs(determinant) > PARALLEL) { // The corner of lines i and j (Cramer).
				consider({ (a.offset * b.normal.y - b.offset * a.normal.y) / determinant,
						(a.normal.x * b.offset - b.normal.x * a.offset) / determinant });
			}
		}
	}
	return best;
}

void FiniteProxy::reset() {
	placed_ = false;
	constraint_count_ = 0;
	active_count_ = 0;
	last_sweeps_ = 0;
}

bool FiniteProxy::try_place(const ConstraintGeometry &p_geometry, const Vec2 &p_point, double p_radius) {
	reset();
	if (is_finite(p_point) && disc_fits(p_geometry, p_point, p_radius)) {
		position_ = p_point;
		placed_ = true;
	}
	return placed_;
}

bool FiniteProxy::sweep(const ConstraintGeometry &p_geometry, const Vec2 &p_from, const Vec2 &p_motion, double p_radius,
		DiscHit &r_hit) const {
	const double slack = 2.0 * PROXY_SKIN * p_radius;
	bool found = false;
	size_t found_index = 0;
	const auto test = [&](size_t p_index) {
		DiscHit hit;
		if (sweep_disc_segment(p_from, p_motion, p_radius, p_geometry.segment(p_index), slack, hit) &&
				(!found || hit.t < r_hit.t || (hit.t == r_hit.t && p_index < found_index))) {
			r_hit = hit;
			found_index = p_index;
			found = true;
		}
	};
	// A long motion (the hand far from a proxy stuck behind walls: common under position
	// control in a maze) is queried in pieces from the start, stopping at the first piece
	// that holds a hit: a wall first touched at t lies near the piece containing t, so no
	// later piece can hold an earlier touch. The cost then follows the walls near the proxy,
	// not the distance to the hand. A wall seen by two pieces is tested twice, harmlessly.
	const double inflate = p_radius + 2.0 * slack;
	const Vec2 margin{ inflate, inflate };
	double begin = 0.0;
	double end = 1.0;
	if (p_geometry.segment_count() == 0 ||
			!clip_to_box(p_from, p_motion, p_geometry.bounds_min() - margin, p_geometry.bounds_max() + margin, begin, end)) {
		return false; // Nothing to touch along the way.
	}
	const double piece = p_geometry.broad_phase() == BroadPhase::UNIFORM_GRID ? std::max(p_geometry.cell_size(), 2.0 * p_radius) : INFINITY;
	const double pieces = std::clamp(std::ceil((end - begin) * length(p_motion) / piece), 1.0, 1e6);
	const int64_t count = static_cast<int64_t>(pieces);
	for (int64_t i = 0; i < count; ++i) {
		const double t0 = begin + (end - begin) * (static_cast<double>(i) / pieces);
		const double t1 = i + 1 == count ? end : begin + (end - begin) * (static_cast<double>(i + 1) / pieces);
		p_geometry.for_each_near(p_from + p_motion * t0, p_from + p_motion * t1, inflate, test);
		// A wall within the slack of this piece may be first touched later: only a touch
		// inside this piece ends the search.
		if (found && r_hit.t <= t1) {
			break;
		}
	}
	return found;
}

void FiniteProxy::update(const ConstraintGeometry &p_geometry, const Vec2 &p_goal, double p_radius,
		uint32_t p_max_iterations) {
	if (!placed_) {
		try_place(p_geometry, p_goal, p_radius);
		return;
	}
	constraint_count_ = 0;
	active_count_ = 0;
	last_sweeps_ = 0;
	if (!is_finite(p_goal)) {
		return; // Hold: a non-finite goal must not become a non-finite proxy.
	}
	const double tolerance = RELATIVE_TOLERANCE * p_radius;
	const double min_motion = MIN_RELATIVE_MOTION * p_radius;
	const uint32_t iterations = std::clamp<uint32_t>(p_max_iterations, 1, MAX_PROXY_ITERATIONS);
	Vec2 proxy = position_;
	for (uint32_t iteration = 0; iteration < iterations; ++iteration) {
		const Vec2 target = project_onto_constraints(p_goal, constraints_, constraint_count_, proxy, tolerance);
		const Vec2 motion = target - proxy;
		const double motion_length = length(motion);
		if (!(motion_length > min_motion)) {
			break;
		}
		++last_sweeps_;
		DiscHit hit;
		if (!sweep(p_geometry, proxy, motion, p_radius, hit)) {
			proxy = target;
			break;
		}
		const double advance = std::max(0.0, hit.t - PROXY_SKIN * p_radius / motion_length);
		proxy += motion * advance;
		bool known = false;
		for (uint32_t c = 0; c < constraint_count_; ++c) {
			known = known || dot(constraints_[c].normal, hit.normal) > SAME_NORMAL;
		}
		if (known) {
			// Rounding made a slide along a known wall look like an approach (or a collinear
			// neighbour's end cap was grazed): keep the progress, add nothing new.
			if (advance > 0.0) {
				continue;
			}
			break;
		}
		if (constraint_count_ == MAX_PROXY_ITERATIONS) {
			break;
		}
		constraints_[constraint_count_++] = ProxyConstraint{ hit.normal, dot(hit.normal, proxy) };
	}
	position_ = proxy;
	// The walls the proxy still rests on: those it was stopped by and did not leave.
	for (uint32_t c = 0; c < constraint_count_; ++c) {
		if (dot(constraints_[c].normal, proxy) - constraints_[c].offset <= PROXY_SKIN * p_radius) {
			++active_count_;
		}
	}
}

} // namespace haptics
