#pragma once

// What the platforms' realtime files (realtime_linux.cpp, realtime_windows.cpp) share: the
// stack prefault once each knows where its thread's stack ends.

#include <cstdint>

namespace haptics {

// Touches up to p_kb KiB of the calling thread's stack below the caller's frame, keeping a
// margin above p_stack_low (the stack's lowest address); returns the KiB touched.
int32_t prefault_stack_above(uintptr_t p_stack_low, int32_t p_kb);

} // namespace haptics
