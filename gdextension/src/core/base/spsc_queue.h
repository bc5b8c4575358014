#pragma once

// A bounded single-producer single-consumer queue (a ring buffer with two monotonically
// increasing indices). Lock-free and wait-free on both sides, no allocation after
// construction: impact events go game -> servo through one, telemetry servo -> game
// through another. A full queue refuses the push; the caller counts the drop.
//
// One thread may push and one (other) thread may pop at a time. Switching which thread plays
// a role is fine when the switch is ordered by something else (e.g. thread start/join).

#include <atomic>
#include <cstddef>
#include <type_traits>

namespace haptics {

template <typename T, size_t CAPACITY>
class SpscQueue {
	static_assert(CAPACITY >= 2 && (CAPACITY & (CAPACITY - 1)) == 0, "CAPACITY must be a power of two");
	static_assert(std::is_trivially_copyable_v<T>);

public:
	static constexpr size_t capacity() { return CAPACITY; }

	// Producer side.
	bool try_push(const T &p_value) {
		const size_t tail = tail_.load(std::memory_order_relaxed);
		if (tail - cached_head_ >= CAPACITY) {
			cached_head_ = head_.load(std::memory_order_acquire);
			if (tail - cached_head_ >= CAPACITY) {
				return false;
			}
		}
		slots_[tail & (CAPACITY - 1)] = p_value;
		tail_.store(tail + 1, std::memory_order_release);
		return true;
	}

	// Consumer side.
	bool try_pop(T &r_value) {
		const size_t head = head_.load(std::memory_order_relaxed);
		if (head == cached_tail_) {
			cached_tail_ = tail_.load(std::memory_order_acquire);
			if (head == cached_tail_) {
				return false;
			}
		}
		r_value = slots_[head & (CAPACITY - 1)];
		head_.store(head + 1, std::memory_order_release);
		return true;
	}

	// Consumer side: drops everything queued so far.
	void clear() {
		T discard;
		while (try_pop(discard)) {
		}
	}

	// Either side; exact only when the other side is idle.
	size_t size_approx() const {
		return tail_.load(std::memory_order_acquire) - head_.load(std::memory_order_acquire);
	}

private:
	alignas(64) std::atomic<size_t> head_{ 0 }; // Next slot to pop; written by the consumer.
	alignas(64) size_t cached_tail_ = 0; // Consumer's private copy of tail_.
	alignas(64) std::atomic<size_t> tail_{ 0 }; // Next slot to fill; written by the producer.
	alignas(64) size_t cached_head_ = 0; // Producer's private copy of head_.
	alignas(64) T slots_[CAPACITY] = {};
};

} // namespace haptics
