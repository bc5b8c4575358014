// The lock-free handoffs between the game thread and the servo: the SPSC queue (impacts,
// telemetry) and the seqlock snapshot (frames, config, output). The two-thread cases are
// what ThreadSanitizer checks in the sanitizer builds.

#include "core/base/seqlock.h"
#include "core/base/spsc_queue.h"

#include <doctest/doctest.h>

#include <atomic>
#include <cstdint>
#include <thread>

using namespace haptics;

namespace {

struct Payload {
	uint64_t words[24] = {}; // Larger than a cache line, so a torn copy would show.
	double value = 0.0;
};

} // namespace

TEST_CASE("spsc queue: FIFO, bounded, refuses when full, clears") {
	SpscQueue<int, 4> queue;
	CHECK(queue.capacity() == 4);
	int out = 0;
	CHECK_FALSE(queue.try_pop(out));
	for (int n = 0; n < 4; ++n) {
		CHECK(queue.try_push(n));
	}
	CHECK_FALSE(queue.try_push(99));
	CHECK(queue.size_approx() == 4);
	for (int n = 0; n < 2; ++n) {
		REQUIRE(queue.try_pop(out));
		CHECK(out == n);
	}
	CHECK(queue.try_push(4)); // Wraps around.
	CHECK(queue.try_push(5));
	CHECK_FALSE(queue.try_push(6));
	for (int n = 2; n < 6; ++n) {
		REQUIRE(queue.try_pop(out));
		CHECK(out == n);
	}
	CHECK(queue.try_push(7));
	queue.clear();
	CHECK(queue.size_approx() == 0);
	CHECK_FALSE(queue.try_pop(out));
}

TEST_CASE("spsc queue: two threads, every item exactly once and in order") {
	constexpr uint64_t COUNT = 100'000;
	SpscQueue<uint64_t, 64> queue;
	std::thread producer([&queue] {
		for (uint64_t n = 0; n < COUNT; ++n) {
			while (!queue.try_push(n)) {
				std::this_thread::yield();
			}
		}
	});
	uint64_t expected = 0;
	uint64_t out_of_order = 0;
	while (expected < COUNT) {
		uint64_t value = 0;
		if (queue.try_pop(value)) {
			out_of_order += value != expected ? 1 : 0;
			++expected;
		} else {
			std::this_thread::yield();
		}
	}
	producer.join();
	CHECK(out_of_order == 0);
	uint64_t extra = 0;
	CHECK_FALSE(queue.try_pop(extra));
}

TEST_CASE("seqlock: a single thread reads what it stored, versions count stores") {
	Seqlock<Payload> snapshot;
	CHECK(snapshot.version() == 1); // The constructor publishes a default value.
	Payload in;
	in.words[7] = 42;
	in.value = 2.5;
	snapshot.store(in);
	CHECK(snapshot.version() == 2);
	Payload out;
	uint64_t version = 0;
	REQUIRE(snapshot.try_load(out, &version));
	CHECK(version == 2);
	CHECK(out.words[7] == 42);
	CHECK(out.value == 2.5);
}

TEST_CASE("seqlock: two threads, a reader never sees a torn or older value") {
	constexpr uint64_t COUNT = 50'000;
	Seqlock<Payload> snapshot;
	std::atomic<bool> done{ false };
	std::thread writer([&] {
		for (uint64_t n = 1; n <= COUNT; ++n) {
			Payload payload;
			for (uint64_t &word : payload.words) {
				word = n;
			}
			payload.value = static_cast<double>(n);
			snapshot.store(payload);
		}
		done.store(true, std::memory_order_release);
	});
	uint64_t torn = 0, went_back = 0, reads = 0, last = 0;
	for (;;) {
		const bool finished = done.load(std::memory_order_acquire);
		Payload payload;
		if (snapshot.try_load(payload)) {
			++reads;
			for (const uint64_t word : payload.words) {
				torn += word != payload.words[0] ? 1 : 0;
			}
			torn += payload.value != static_cast<double>(payload.words[0]) ? 1 : 0;
			went_back += payload.words[0] < last ? 1 : 0;
			last = payload.words[0];
		}
		if (finished) {
			break;
		}
	}
	writer.join();
	CHECK(torn == 0);
	CHECK(went_back == 0);
	CHECK(reads > 0);
	CHECK(snapshot.load().words[0] == COUNT); // The last complete value wins.
}
