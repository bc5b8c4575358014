#include "renderers/constraint/constraint_port.h"

#include "renderers/constraint/constraint_geometry.h"

#include <memory>
#include <utility>

namespace haptics {

ConstraintPort::ConstraintPort(ConstraintChannels &r_channels) :
		channels_(r_channels) {}

Status ConstraintPort::set_geometry(const Segment2 *p_segments, size_t p_count, const MazeMapping &p_mapping) {
	std::unique_ptr<ConstraintGeometry> geometry;
	const Status built = ConstraintGeometry::build(p_segments, p_count, p_mapping, BroadPhase::UNIFORM_GRID, geometry);
	if (!built) {
		return built;
	}
	channels_.geometry.publish(std::move(geometry));
	return Status::success();
}

ProxyState ConstraintPort::state() const {
	return channels_.state.load();
}

} // namespace haptics
