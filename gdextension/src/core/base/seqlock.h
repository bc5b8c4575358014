#pragma once

// A single-writer snapshot of a trivially copyable value (a seqlock). The writer never waits
// and never allocates, which is what the servo thread needs on both sides: it publishes its
// output at 1 kHz to a game thread that may be slow, and reads the game's latest frame
// without ever blocking behind it. A reader can fail (the writer was mid-update); the servo
// then keeps its previous copy and tries again next tick, the game thread simply retries.
//
// The payload is stored as atomic 64-bit words rather than plain bytes: a seqlock over
// plain memory is a data race by the C++ memory model (and ThreadSanitizer says so). Word
// stores are release and word loads acquire instead of relaxed-plus-fences (H. Boehm, "Can
// seqlocks get along with programming language memory models?", 2012): a reader that sees
// any word of a newer store then also sees the odd sequence number written before it, so
// its final check fails and it retries. On x86-64 these are the same plain moves; on ARM64
// they are LDAR/STLR. ThreadSanitizer models this exactly (it does not model fences).
//
// Exactly one thread may call store(); any number may read.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace haptics {

template <typename T>
class Seqlock {
	static_assert(std::is_trivially_copyable_v<T>, "Seqlock copies bytes");
	static_assert(std::is_default_constructible_v<T>);

public:
	Seqlock() { store(T{}); }

	void store(const T &p_value) {
		uint64_t buffer[WORDS] = {};
		std::memcpy(buffer, &p_value, sizeof(T));
		const uint64_t sequence = sequence_.load(std::memory_order_relaxed);
		sequence_.store(sequence + 1, std::memory_order_relaxed); // Odd: writing.
		for (size_t w = 0; w < WORDS; ++w) {
			words_[w].store(buffer[w], std::memory_order_release);
		}
		sequence_.store(sequence + 2, std::memory_order_release);
	}

	// Copies the latest complete value into r_value and its version into r_version (when
	// given); returns false, leaving r_value alone, if a store was in progress.
	bool try_load(T &r_value, uint64_t *r_version = nullptr) const {
		const uint64_t before = sequence_.load(std::memory_order_acquire);
		if (before & 1u) {
			return false;
		}
		uint64_t buffer[WORDS];
		for (size_t w = 0; w < WORDS; ++w) {
			buffer[w] = words_[w].load(std::memory_order_acquire);
		}
		if (sequence_.load(std::memory_order_relaxed) != before) {
			return false;
		}
		std::memcpy(&r_value, buffer, sizeof(T));
		if (r_version) {
			*r_version = before / 2;
		}
		return true;
	}

	// Retries until a consistent copy is read; for readers that may wait (the game thread).
	T load() const {
		T value{};
		while (!try_load(value)) {
		}
		return value;
	}

	// Number of completed stores since construction (the constructor's counts as one).
	uint64_t version() const { return sequence_.load(std::memory_order_acquire) / 2; }

private:
	static constexpr size_t WORDS = (sizeof(T) + sizeof(uint64_t) - 1) / sizeof(uint64_t);

	alignas(64) std::atomic<uint64_t> sequence_{ 0 };
	std::atomic<uint64_t> words_[WORDS] = {};
};

} // namespace haptics
