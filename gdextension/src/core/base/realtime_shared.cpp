#include "core/base/realtime_shared.h"
#include "core/base/realtime.h"

#include <algorithm>
#include <cstddef>

#ifdef _WIN32
#include <malloc.h>
#else
#include <alloca.h>
#endif

namespace haptics {

namespace {

// Stack left untouched below the prefaulted part: the tick's own frames and signal handlers.
constexpr size_t STACK_MARGIN_BYTES = 64 * 1024;
constexpr size_t PAGE_STRIDE = 4096;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#elif defined(__aarch64__)
	asm volatile("yield");
#endif
}

// Touches p_bytes below this frame, a page at a time, through a volatile pointer (the
// compiler may not drop the writes).
__attribute__((noinline)) void touch_stack(size_t p_bytes) {
	volatile unsigned char *area = static_cast<volatile unsigned char *>(alloca(p_bytes));
	for (size_t offset = 0; offset < p_bytes; offset += PAGE_STRIDE) {
		area[offset] = 0;
	}
	area[p_bytes - 1] = 0;
}

} // namespace

int64_t sleep_then_spin_until_ns(int64_t p_deadline_ns, int64_t p_spin_ns) {
	if (p_spin_ns <= 0) {
		sleep_until_ns(p_deadline_ns);
		return monotonic_now_ns();
	}
	sleep_until_ns(p_deadline_ns - p_spin_ns);
	const int64_t woke_ns = monotonic_now_ns();
	for (int64_t now_ns = woke_ns; now_ns < p_deadline_ns; now_ns = monotonic_now_ns()) {
		cpu_relax();
	}
	return woke_ns;
}

int32_t prefault_stack_above(uintptr_t p_stack_low, int32_t p_kb) {
	unsigned char here = 0;
	const uintptr_t current = reinterpret_cast<uintptr_t>(&here);
	if (current <= p_stack_low + STACK_MARGIN_BYTES) {
		return 0;
	}
	const size_t available = current - p_stack_low - STACK_MARGIN_BYTES;
	const size_t bytes = std::min(static_cast<size_t>(p_kb) * 1024, available) / PAGE_STRIDE * PAGE_STRIDE;
	if (bytes == 0) {
		return 0;
	}
	touch_stack(bytes);
	return static_cast<int32_t>(bytes / 1024);
}

} // namespace haptics
