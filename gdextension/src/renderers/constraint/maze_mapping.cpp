#include "renderers/constraint/maze_mapping.h"

#include "core/base/value_checks.h"

#include <algorithm>
#include <cmath>

namespace haptics {

namespace {

constexpr double MAX_COORDINATE = 1e9;

Status check_point(const char *p_name, const Vec2 &p_point, double p_max) {
	if (!is_finite(p_point)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: not finite (%g, %g)", p_name, p_point.x, p_point.y);
	}
	if (std::abs(p_point.x) > p_max || std::abs(p_point.y) > p_max) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s: coordinates must be within +-%g (got %g, %g)", p_name, p_max,
				p_point.x, p_point.y);
	}
	return Status::success();
}

} // namespace

MazeTransform resolve_maze_mapping(const MazeMapping &p_mapping, double p_device_radius_m) {
	const double half_extent = p_mapping.workspace_half_extent_m > 0.0 ? p_mapping.workspace_half_extent_m : p_device_radius_m;
	const Vec2 size = p_mapping.maze_max - p_mapping.maze_min;
	const double span = p_mapping.workspace_shape == WorkspaceShape::DISC ? length(size) : std::max(size.x, size.y);
	MazeTransform transform;
	transform.maze_centre = (p_mapping.maze_min + p_mapping.maze_max) * 0.5;
	transform.device_centre_m = p_mapping.workspace_centre_m;
	transform.metres_per_unit = 2.0 * half_extent / span;
	transform.y_sign = p_mapping.maze_y_down ? -1.0 : 1.0;
	return transform;
}

Status validate_maze_mapping(const MazeMapping &p_mapping) {
	Status status = check_point("mapping.maze_min", p_mapping.maze_min, MAX_COORDINATE);
	if (!status) {
		return status;
	}
	status = check_point("mapping.maze_max", p_mapping.maze_max, MAX_COORDINATE);
	if (!status) {
		return status;
	}
	if (!(p_mapping.maze_max.x > p_mapping.maze_min.x)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "mapping.maze_max.x must be > mapping.maze_min.x (got %g <= %g)",
				p_mapping.maze_max.x, p_mapping.maze_min.x);
	}
	if (!(p_mapping.maze_max.y > p_mapping.maze_min.y)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "mapping.maze_max.y must be > mapping.maze_min.y (got %g <= %g)",
				p_mapping.maze_max.y, p_mapping.maze_min.y);
	}
	if (p_mapping.workspace_shape != WorkspaceShape::DISC && p_mapping.workspace_shape != WorkspaceShape::SQUARE) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "mapping.workspace_shape: unknown shape %d",
				static_cast<int>(p_mapping.workspace_shape));
	}
	if (p_mapping.workspace_half_extent_m != 0.0) {
		status = check_range("mapping.workspace_half_extent_m", p_mapping.workspace_half_extent_m, 0.001, 1.0);
		if (!status) {
			return status;
		}
	}
	status = check_point("mapping.workspace_centre_m", p_mapping.workspace_centre_m, 1.0);
	return status;
}

} // namespace haptics
