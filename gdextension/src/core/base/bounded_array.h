#pragma once

// A fixed-capacity array with a count: what a realtime value (one the servo thread reads
// through a seqlock or a ring) holds instead of a std::vector, so it stays trivially
// copyable and never allocates.

#include <array>
#include <cstddef>
#include <cstdint>

namespace haptics {

template <typename T, size_t N>
struct BoundedArray {
	static constexpr size_t CAPACITY = N;

	std::array<T, N> items{};
	uint32_t count = 0;

	size_t size() const { return count; }
	bool empty() const { return count == 0; }
	bool full() const { return count >= N; }
	T &operator[](size_t p_index) { return items[p_index]; }
	const T &operator[](size_t p_index) const { return items[p_index]; }
	T *begin() { return items.data(); }
	T *end() { return items.data() + count; }
	const T *begin() const { return items.data(); }
	const T *end() const { return items.data() + count; }
	void clear() { count = 0; }
	// False (and nothing added) when full.
	bool push_back(const T &p_item) {
		if (count >= N) {
			return false;
		}
		items[count++] = p_item;
		return true;
	}
};

} // namespace haptics
