#include "renderers/pong/court.h"

namespace haptics {

void court_planes(const PongConfig &p_config, CourtPlane (&r_planes)[COURT_SURFACE_COUNT]) {
	const double w = court_half_x(p_config);
	const double l = court_half_z(p_config);
	r_planes[0] = { CourtSurface::LEFT, { 1.0, 0.0, 0.0 }, -w };
	r_planes[1] = { CourtSurface::RIGHT, { -1.0, 0.0, 0.0 }, -w };
	r_planes[2] = { CourtSurface::BACK_NEAR, { 0.0, 0.0, -1.0 }, -l };
	r_planes[3] = { CourtSurface::BACK_FAR, { 0.0, 0.0, 1.0 }, -l };
	r_planes[4] = { CourtSurface::CEILING, { 0.0, -1.0, 0.0 }, -p_config.wall_height_m };
	r_planes[5] = { CourtSurface::FLOOR, { 0.0, 1.0, 0.0 }, 0.0 };
}

} // namespace haptics
