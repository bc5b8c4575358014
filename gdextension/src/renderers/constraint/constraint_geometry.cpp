#include "renderers/constraint/constraint_geometry.h"

#include <cstdio>
#include <utility>

namespace haptics {

namespace {

constexpr double MAX_COORDINATE = 1e9;
// Shorter than this fraction of the whole set's extent is a point, not a wall: it has no
// direction to slide along and its "normal" would be rounding noise.
constexpr double MIN_RELATIVE_LENGTH = 1e-9;
constexpr int32_t MAX_CELLS_PER_AXIS = 4096;
constexpr double MAX_CELLS_PER_SEGMENT = 4.0;
constexpr double CELL_GROWTH = 1.25;

Status check_end(const char *p_end, size_t p_index, const Vec2 &p_point) {
	if (!is_finite(p_point)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "constraint.segments[%zu].%s: not finite (%g, %g)", p_index,
				p_end, p_point.x, p_point.y);
	}
	if (std::abs(p_point.x) > MAX_COORDINATE || std::abs(p_point.y) > MAX_COORDINATE) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"constraint.segments[%zu].%s: coordinates must be within +-%g (got %g, %g)", p_index, p_end, MAX_COORDINATE,
				p_point.x, p_point.y);
	}
	return Status::success();
}

} // namespace

Status validate_constraint_segments(const Segment2 *p_segments, size_t p_count) {
	if (p_count > MAX_CONSTRAINT_SEGMENTS) {
		return Status::error(StatusCode::OUT_OF_RANGE, "constraint.segments: count must be <= %zu (got %zu)",
				MAX_CONSTRAINT_SEGMENTS, p_count);
	}
	if (p_count > 0 && p_segments == nullptr) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "constraint.segments: null with count %zu", p_count);
	}
	Vec2 low{ MAX_COORDINATE, MAX_COORDINATE };
	Vec2 high{ -MAX_COORDINATE, -MAX_COORDINATE };
	for (size_t s = 0; s < p_count; ++s) {
		for (const auto &[name, point] : { std::pair{ "a", p_segments[s].a }, std::pair{ "b", p_segments[s].b } }) {
			const Status end = check_end(name, s, point);
			if (!end) {
				return end;
			}
			low = { std::min(low.x, point.x), std::min(low.y, point.y) };
			high = { std::max(high.x, point.x), std::max(high.y, point.y) };
		}
	}
	const double min_length = MIN_RELATIVE_LENGTH * std::max(high.x - low.x, high.y - low.y);
	for (size_t s = 0; s < p_count; ++s) {
		const double segment_length = length(p_segments[s].b - p_segments[s].a);
		if (!(segment_length > min_length)) {
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"constraint.segments[%zu]: degenerate (length %g, ends at (%g, %g)); a wall needs two distinct ends", s,
					segment_length, p_segments[s].a.x, p_segments[s].a.y);
		}
	}
	return Status::success();
}

void append_closed_chain(const Vec2 *p_points, size_t p_count, std::vector<Segment2> &r_segments) {
	if (p_points == nullptr || p_count < 2) {
		return;
	}
	for (size_t p = 0; p < p_count; ++p) {
		const Vec2 &a = p_points[p];
		const Vec2 &b = p_points[(p + 1) % p_count];
		if (!(a == b)) {
			r_segments.push_back(Segment2{ a, b });
		}
	}
}

Status ConstraintGeometry::build(const Segment2 *p_segments, size_t p_count, const MazeMapping &p_mapping,
		BroadPhase p_broad_phase, std::unique_ptr<ConstraintGeometry> &r_geometry) {
	Status status = validate_constraint_segments(p_segments, p_count);
	if (!status) {
		return status;
	}
	status = validate_maze_mapping(p_mapping);
	if (!status) {
		return status;
	}
	if (p_broad_phase != BroadPhase::UNIFORM_GRID && p_broad_phase != BroadPhase::BRUTE_FORCE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "constraint.broad_phase: unknown kind %d",
				static_cast<int>(p_broad_phase));
	}
	std::unique_ptr<ConstraintGeometry> geometry(new ConstraintGeometry());
	geometry->segments_.assign(p_segments, p_segments + p_count);
	geometry->mapping_ = p_mapping;
	geometry->broad_phase_ = p_broad_phase;
	if (p_count > 0) {
		Vec2 low = p_segments[0].a;
		Vec2 high = low;
		for (size_t s = 0; s < p_count; ++s) {
			for (const Vec2 &point : { p_segments[s].a, p_segments[s].b }) {
				low = { std::min(low.x, point.x), std::min(low.y, point.y) };
				high = { std::max(high.x, point.x), std::max(high.y, point.y) };
			}
		}
		geometry->bounds_min_ = low;
		geometry->bounds_max_ = high;
	}
	if (p_broad_phase == BroadPhase::UNIFORM_GRID && p_count > 0) {
		geometry->build_grid();
	}
	r_geometry = std::move(geometry);
	return Status::success();
}

void ConstraintGeometry::build_grid() {
	const Vec2 low = bounds_min_;
	const Vec2 high = bounds_max_;
	std::vector<double> lengths;
	lengths.reserve(segments_.size());
	for (const Segment2 &segment : segments_) {
		lengths.push_back(length(segment.b - segment.a));
	}
	// The median, not the mean: a few long outer walls must not make every cell huge.
	std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
	const Vec2 extent = high - low;
	const double max_cells = MAX_CELLS_PER_SEGMENT * static_cast<double>(segments_.size()) + 64.0;
	double cell = lengths[lengths.size() / 2];
	for (;;) {
		const double columns = std::floor(extent.x / cell) + 1.0;
		const double rows = std::floor(extent.y / cell) + 1.0;
		if (columns <= MAX_CELLS_PER_AXIS && rows <= MAX_CELLS_PER_AXIS && columns * rows <= max_cells) {
			columns_ = static_cast<int32_t>(columns);
			rows_ = static_cast<int32_t>(rows);
			break;
		}
		cell *= CELL_GROWTH;
	}
	origin_ = low;
	cell_size_ = cell;
	inverse_cell_size_ = 1.0 / cell;
	// Two passes over the same cells: count, then fill (CSR). Segments are listed in the
	// cells they cross exactly, with no margin: a wall lying on a cell boundary is listed
	// once, not twice. Rounding there cannot lose it, because every query is inflated by the
	// proxy's touch slack (2e-6 r) beyond what the narrow phase tests.
	const size_t cells = static_cast<size_t>(columns_) * static_cast<size_t>(rows_);
	cell_start_.assign(cells + 1, 0);
	segment_rows_.resize(segments_.size());
	const auto for_each_cell = [this](size_t p_index, auto &&p_apply) {
		const Segment2 &segment = segments_[p_index];
		const RowRange rows = segment_rows_[p_index];
		for (int32_t row = rows.first; row <= rows.last; ++row) {
			const Span span = row_span(segment.a, segment.b, 0.0, row);
			for (int32_t column = span.lo; column <= span.hi; ++column) {
				p_apply(static_cast<size_t>(row) * static_cast<size_t>(columns_) + static_cast<size_t>(column), span.lo);
			}
		}
	};
	for (size_t s = 0; s < segments_.size(); ++s) {
		segment_rows_[s] = rows_of(segments_[s].a, segments_[s].b, 0.0);
		for_each_cell(s, [this](size_t p_cell, int32_t) { ++cell_start_[p_cell + 1]; });
	}
	for (size_t c = 0; c < cells; ++c) {
		cell_start_[c + 1] += cell_start_[c];
	}
	cell_items_.resize(cell_start_[cells]);
	std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
	for (size_t s = 0; s < segments_.size(); ++s) {
		for_each_cell(s, [&](size_t p_cell, int32_t p_first_column) {
			cell_items_[fill[p_cell]++] = CellEntry{ static_cast<uint32_t>(s), p_first_column };
		});
	}
}

ConstraintGeometry::Span ConstraintGeometry::row_span(const Vec2 &p_from, const Vec2 &p_to, double p_inflate,
		int32_t p_row) const {
	// Clip the centre line to the row's band widened by the radius, then widen the clipped
	// piece's x extent by the radius: every capsule point in the row is within the radius of
	// a centre-line point in the widened band.
	const double band_low = origin_.y + static_cast<double>(p_row) * cell_size_ - p_inflate;
	const double band_high = origin_.y + static_cast<double>(p_row + 1) * cell_size_ + p_inflate;
	const Vec2 motion = p_to - p_from;
	double t0 = 0.0;
	double t1 = 1.0;
	if (motion.y == 0.0) {
		if (p_from.y < band_low || p_from.y > band_high) {
			return { 1, 0 };
		}
	} else {
		double enter = (band_low - p_from.y) / motion.y;
		double leave = (band_high - p_from.y) / motion.y;
		if (enter > leave) {
			std::swap(enter, leave);
		}
		t0 = std::max(t0, enter);
		t1 = std::min(t1, leave);
		if (t0 > t1) {
			return { 1, 0 };
		}
	}
	const double x0 = p_from.x + motion.x * t0;
	const double x1 = p_from.x + motion.x * t1;
	return { column_of(std::min(x0, x1) - p_inflate), column_of(std::max(x0, x1) + p_inflate) };
}

bool ConstraintGeometry::is_first_shared_cell(const CellEntry &p_entry, const Vec2 &p_from, const Vec2 &p_to,
		double p_inflate, int32_t p_query_first_row, int32_t p_query_first_column, int32_t p_column, int32_t p_row) const {
	// In this row, the first shared column is the later of the two spans' starts.
	if (p_column != std::max(p_entry.first_column, p_query_first_column)) {
		return false;
	}
	// And no earlier row may share a cell. Most walls cross one row, or are met in their
	// first row: no geometry needed. Otherwise both spans are recomputed for earlier rows.
	const Segment2 &segment = segments_[p_entry.segment];
	for (int32_t row = std::max(segment_rows_[p_entry.segment].first, p_query_first_row); row < p_row; ++row) {
		const Span mine = row_span(segment.a, segment.b, 0.0, row);
		const Span query = row_span(p_from, p_to, p_inflate, row);
		if (std::max(mine.lo, query.lo) <= std::min(mine.hi, query.hi)) {
			return false;
		}
	}
	return true;
}

} // namespace haptics
