#include "renderers/constraint/geometry_exchange.h"

namespace haptics {

GeometryExchange::~GeometryExchange() {
	delete pending_.exchange(nullptr, std::memory_order_acquire);
	delete retired_.exchange(nullptr, std::memory_order_acquire);
	delete current_;
}

void GeometryExchange::publish(std::unique_ptr<ConstraintGeometry> p_geometry) {
	collect();
	// A previous geometry still pending was never seen by the servo: it is ours to free.
	delete pending_.exchange(p_geometry.release(), std::memory_order_acq_rel);
}

void GeometryExchange::collect() {
	if (retired_.load(std::memory_order_relaxed) != nullptr) {
		delete retired_.exchange(nullptr, std::memory_order_acquire);
	}
}

GeometryExchange::Current GeometryExchange::acquire() {
	// Cheap when nothing changed: one relaxed load. The slot for the replaced geometry must
	// be free before the swap (only the game empties it, only this side fills it).
	if (pending_.load(std::memory_order_relaxed) == nullptr || retired_.load(std::memory_order_acquire) != nullptr) {
		return current();
	}
	ConstraintGeometry *next = pending_.exchange(nullptr, std::memory_order_acq_rel);
	if (next == nullptr) {
		return current();
	}
	if (current_ != nullptr) {
		retired_.store(current_, std::memory_order_release);
	}
	current_ = next;
	++generation_;
	return current();
}

} // namespace haptics
