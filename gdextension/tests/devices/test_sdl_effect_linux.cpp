// SDL's Linux driver turns the SDL backend's polar angle (devices/sdl/sdl_effect.h) into the
// very evdev direction our evdev backend sends (devices/evdev/evdev_ff.h, which only Linux builds).

#include "devices/evdev/evdev_ff.h"
#include "devices/sdl/sdl_effect.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>

using namespace haptics;
using namespace haptics::sdl;

namespace {

// SDL's Linux driver: polar hundredths of a degree -> ff_effect direction
// (SDL_SYS_ToDirection, src/haptic/linux/SDL_syshaptic.c).
uint16_t linux_direction(int32_t p_polar) {
	return static_cast<uint16_t>(((static_cast<uint32_t>(p_polar) % 36000) * 0x8000) / 18000);
}

} // namespace

TEST_CASE("sdl effect: on Linux SDL hands the kernel the evdev backend's own direction for every force") {
	const SdlForceMapping sdl_mapping{ 5.0, false, false, false };
	const evdev::FfForceMapping evdev_mapping{ 5.0, evdev::EvdevShape::JOYSTICK, false, false };
	for (int i = 0; i < 360; i += 7) {
		const double angle = i * 3.14159265358979 / 180.0;
		const Vec3 force(2.0 * std::sin(angle), 2.0 * std::cos(angle), 0.0);
		CAPTURE(i);
		const SdlConstantForce sdl_force = map_force_to_sdl(force, sdl_mapping);
		const evdev::FfConstantForce evdev_force = evdev::map_force_to_constant(force, evdev_mapping);
		const int difference = static_cast<int>(linux_direction(sdl_force.direction)) - evdev_force.direction;
		// SDL's hundredths of a degree are coarser than evdev's 1/65536 of a turn: 2 steps at most.
		CHECK(std::abs(difference) <= 2);
		CHECK(sdl_force.level == evdev_force.level);
	}
}
