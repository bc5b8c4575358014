#pragma once

// The maze's static walls as the finite proxy sees them: a copy of the level's segments, in
// maze units, with a uniform-grid broad phase built once when the geometry is loaded.
//
// Broad phase: a uniform grid over the segments' bounding box. Each segment is listed in the
// cells it actually crosses (row by row, not its bounding box, so a long diagonal wall does
// not fill the whole grid); the cells are stored flat (CSR: per-cell start offsets into one
// index array). A query for a disc of radius r swept from p to q visits, row by row, only
// the cells the swept capsule can touch, and reports each segment once without any scratch
// state: a segment is reported from the first cell (row-major) that both it and the query
// cover. So queries are pure and const, the object is immutable after build(), and the tick
// cost depends on how many walls are near the proxy, not on how many walls there are.
//
// Cell size: the segments' median length, enlarged until there are at most ~4 cells per
// segment (and 4096 per axis): a maze wall then spans one or two cells and a cell holds a
// handful of walls. Long motions are queried piece by piece (finite_proxy.cpp), so a query
// stays a few cells wide however far the hand is from the proxy.
//
// Allocation happens only in build(), on the caller's thread (the game's, at level load).

#include "core/base/status.h"
#include "renderers/constraint/maze_mapping.h"
#include "renderers/constraint/swept_disc.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace haptics {

inline constexpr size_t MAX_CONSTRAINT_SEGMENTS = size_t{ 1 } << 18; // 262 144 walls.

enum class BroadPhase : int32_t {
	UNIFORM_GRID = 0, // The product.
	BRUTE_FORCE = 1, // Every query visits every segment: the benchmark's and tests' baseline.
};

// Finite, |coordinate| <= 1e9, and not degenerate: every segment at least 1e-9 of the
// extent of the whole set long. Messages name the index, e.g.
// "constraint.segments[12].b: not finite (nan, 3)" or "constraint.segments[4]: degenerate
// (length 0, ends at (2, 3))". p_segments may be null only when p_count is 0.
Status validate_constraint_segments(const Segment2 *p_segments, size_t p_count);

// Appends the edges of the polygon p_points[0] -> p_points[1] -> ... -> p_points[0] (a
// collision polygon's outline) to r_segments, skipping zero-length edges from repeated
// vertices. Fewer than two distinct points add nothing.
void append_closed_chain(const Vec2 *p_points, size_t p_count, std::vector<Segment2> &r_segments);

class ConstraintGeometry {
public:
	// Validates (validate_constraint_segments, validate_maze_mapping), copies and indexes.
	// On error r_geometry is left untouched.
	static Status build(const Segment2 *p_segments, size_t p_count, const MazeMapping &p_mapping,
			BroadPhase p_broad_phase, std::unique_ptr<ConstraintGeometry> &r_geometry);

	// Calls p_visit(index) once for every segment that may come within p_inflate of the
	// segment p_from -> p_to (a superset of those that do; BRUTE_FORCE visits them all).
	template <typename Visit>
	void for_each_near(const Vec2 &p_from, const Vec2 &p_to, double p_inflate, Visit &&p_visit) const;

	size_t segment_count() const { return segments_.size(); }
	const Segment2 &segment(size_t p_index) const { return segments_[p_index]; }
	const MazeMapping &mapping() const { return mapping_; }
	BroadPhase broad_phase() const { return broad_phase_; }
	int32_t grid_columns() const { return columns_; }
	int32_t grid_rows() const { return rows_; }
	double cell_size() const { return cell_size_; }
	// Bounding box of all segments (both zero without segments).
	const Vec2 &bounds_min() const { return bounds_min_; }
	const Vec2 &bounds_max() const { return bounds_max_; }
	size_t grid_entries() const { return cell_items_.size(); } // Segment-in-cell listings.

private:
	struct Span {
		int32_t lo;
		int32_t hi; // Inclusive; empty when lo > hi.
	};
	struct RowRange {
		int32_t first;
		int32_t last;
	};
	// One listing of a segment in a cell, with the first column the segment covers in that
	// row, so the common case of the de-duplication needs no geometry.
	struct CellEntry {
		uint32_t segment;
		int32_t first_column;
	};

	ConstraintGeometry() = default;
	void build_grid();
	int32_t column_of(double p_x) const { return clamp_cell((p_x - origin_.x) * inverse_cell_size_, columns_); }
	int32_t row_of(double p_y) const { return clamp_cell((p_y - origin_.y) * inverse_cell_size_, rows_); }
	static int32_t clamp_cell(double p_cell, int32_t p_count) {
		const double cell = std::floor(p_cell);
		return cell <= 0.0 ? 0 : (cell >= p_count - 1 ? p_count - 1 : static_cast<int32_t>(cell));
	}
	// Columns of row p_row that the capsule (p_from -> p_to, radius p_inflate) can touch.
	Span row_span(const Vec2 &p_from, const Vec2 &p_to, double p_inflate, int32_t p_row) const;
	RowRange rows_of(const Vec2 &p_from, const Vec2 &p_to, double p_inflate) const {
		return { row_of(std::min(p_from.y, p_to.y) - p_inflate), row_of(std::max(p_from.y, p_to.y) + p_inflate) };
	}
	// Is cell (p_column, p_row), which lists p_entry and which the query covers from column
	// p_query_first_column on, the first cell (row-major) that the segment shares with the
	// query? That is where the segment is reported.
	bool is_first_shared_cell(const CellEntry &p_entry, const Vec2 &p_from, const Vec2 &p_to, double p_inflate,
			int32_t p_query_first_row, int32_t p_query_first_column, int32_t p_column, int32_t p_row) const;

	std::vector<Segment2> segments_;
	std::vector<RowRange> segment_rows_; // Grid rows each segment crosses.
	std::vector<uint32_t> cell_start_; // columns * rows + 1 offsets into cell_items_.
	std::vector<CellEntry> cell_items_; // Ascending segment index within a cell.
	MazeMapping mapping_;
	BroadPhase broad_phase_ = BroadPhase::UNIFORM_GRID;
	Vec2 bounds_min_;
	Vec2 bounds_max_;
	Vec2 origin_;
	double cell_size_ = 1.0;
	double inverse_cell_size_ = 1.0;
	int32_t columns_ = 1;
	int32_t rows_ = 1;
};

template <typename Visit>
void ConstraintGeometry::for_each_near(const Vec2 &p_from, const Vec2 &p_to, double p_inflate, Visit &&p_visit) const {
	const size_t count = segments_.size();
	if (broad_phase_ == BroadPhase::BRUTE_FORCE || count == 0) {
		for (size_t s = 0; s < count; ++s) {
			p_visit(s);
		}
		return;
	}
	const RowRange rows = rows_of(p_from, p_to, p_inflate);
	for (int32_t row = rows.first; row <= rows.last; ++row) {
		const Span span = row_span(p_from, p_to, p_inflate, row);
		for (int32_t column = span.lo; column <= span.hi; ++column) {
			const size_t cell = static_cast<size_t>(row) * static_cast<size_t>(columns_) + static_cast<size_t>(column);
			for (uint32_t item = cell_start_[cell]; item < cell_start_[cell + 1]; ++item) {
				const CellEntry &entry = cell_items_[item];
				if (is_first_shared_cell(entry, p_from, p_to, p_inflate, rows.first, span.lo, column, row)) {
					p_visit(entry.segment);
				}
			}
		}
	}
}

} // namespace haptics
