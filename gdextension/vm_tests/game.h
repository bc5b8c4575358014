#pragma once

// The game's side of the scenarios: finding a device in the picker's list, sending frames
// the way a game does, and watching the servo stop.

#include "devices/device_info.h"
#include "engine/haptics_engine.h"

#include <cstdint>
#include <string_view>

namespace haptics::vm {

// The first entry of list_all_devices() with these ids on p_backend.
bool find_listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend, DeviceInfo &r_info);

// The game's frames at 50 Hz for p_seconds: the player stands on a floor.
void stand_on_floor(HapticsEngine &p_engine, double p_seconds);

// Whether the servo stops within p_seconds (it notices a device fault at its next tick, which
// under emulation may come a while after the device's I/O thread raised it).
bool servo_stops(const HapticsEngine &p_engine, double p_seconds);

} // namespace haptics::vm
