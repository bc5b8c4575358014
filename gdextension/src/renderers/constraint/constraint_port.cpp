#include "renderers/constraint/constraint_port.h"

#include "renderers/constraint/constraint_geometry.h"

#include <memory>
#include <utility>
#include <vector>

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

Status ConstraintPort::receive(std::span<const uint8_t> p_message) {
	return receive_one_of<MazeWalls>(p_message, [&](const MazeWalls &p_walls) {
		if (p_walls.points.size() % 2 != 0) {
			return Status::error(StatusCode::INVALID_ARGUMENT,
					"HapticMazeWalls.points: %zu points; walls are point pairs, so it must be even", p_walls.points.size());
		}
		std::vector<Segment2> segments(p_walls.points.size() / 2);
		for (size_t s = 0; s < segments.size(); ++s) {
			segments[s] = Segment2{ p_walls.points[2 * s], p_walls.points[2 * s + 1] };
		}
		return set_geometry(segments.data(), segments.size(), p_walls.mapping);
	});
}

Status ConstraintPort::give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) {
	if (p_value_id != ProxyState::SCHEMA_ID) {
		return Status::error(StatusCode::INVALID_ARGUMENT,
				"the constraint renderer gives ProxyState, not layout %08x", unsigned(p_value_id));
	}
	r_bytes = encode(state());
	return Status::success();
}

ProxyState ConstraintPort::state() const {
	return channels_.state.load();
}

} // namespace haptics
