// The SDL backend's effects (devices/sdl/sdl_effect.h): a stick's force as SDL's polar angle and
// level; a wheel's on the steering axis; finite values within full scale whatever comes in; the
// rumble envelope's two motors. Against the evdev backend's directions: test_sdl_effect_linux.cpp.

#include "devices/sdl/sdl_effect.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace haptics;
using namespace haptics::sdl;

TEST_CASE("sdl effect: a stick's force as a polar angle clockwise from device +y and a level of full scale") {
	const SdlForceMapping mapping{ 5.0, false, false, false };
	const struct {
		Vec3 force;
		int32_t direction;
		int16_t level;
	} cases[] = {
		{ Vec3(1.0, 0.0, 0.0), 9000, 6553 }, // 1 N of 5: 0.2 * 32767 = 6553.4
		{ Vec3(0.0, -2.5, 0.0), 18000, 16384 },
		{ Vec3(-5.0, 0.0, 0.0), 27000, 32767 },
		{ Vec3(0.0, 1.0, 0.0), 0, 6553 },
		{ Vec3(1.0, 1.0, 0.0), 4500, 9268 }, // |F| = sqrt 2
		{ Vec3(0.0, 0.0, 3.0), 0, 0 }, // z is not rendered
	};
	for (const auto &c : cases) {
		CAPTURE(c.direction);
		const SdlConstantForce force = map_force_to_sdl(c.force, mapping);
		CHECK(force.direction_type == SDL_HAPTIC_POLAR);
		CHECK(force.direction == c.direction);
		CHECK(force.level == c.level);
	}
}

TEST_CASE("sdl effect: NaN and infinities count as zero, huge forces are full scale, never beyond") {
	const SdlForceMapping mapping{ 5.0, false, false, false };
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	CHECK(map_force_to_sdl(Vec3(nan, nan, 0.0), mapping) == SdlConstantForce{});
	CHECK(map_force_to_sdl(Vec3(inf, 0.0, 0.0), mapping) == SdlConstantForce{});
	const SdlConstantForce huge = map_force_to_sdl(Vec3(0.0, -1e9, 0.0), mapping);
	CHECK(huge.level == SDL_LEVEL_MAX);
	CHECK(huge.direction == 18000);
	const Vec3 rendered = constant_effect_force_n(constant_effect(huge), 5.0);
	CHECK(length(rendered) == doctest::Approx(5.0));
	SdlForceMapping wheel = mapping;
	wheel.steering = true;
	CHECK(map_force_to_sdl(Vec3(-1e9, 0.0, 0.0), wheel).level == -SDL_LEVEL_MAX);
	CHECK(map_force_to_sdl(Vec3(nan, 3.0, 0.0), wheel).level == 0);
}

TEST_CASE("sdl effect: a wheel renders x on the steering axis with a signed level, y is not felt") {
	const SdlForceMapping wheel{ 4.0, true, false, false };
	const SdlConstantForce right = map_force_to_sdl(Vec3(1.0, 3.0, 0.0), wheel);
	CHECK(right.direction_type == SDL_HAPTIC_STEERING_AXIS);
	CHECK(right.direction == 0);
	CHECK(right.level == 8192); // 0.25 * 32767 = 8191.75
	CHECK(map_force_to_sdl(Vec3(-1.0, 0.0, 0.0), wheel).level == -8192);
	SdlForceMapping inverted = wheel;
	inverted.invert_x = true;
	CHECK(map_force_to_sdl(Vec3(-1.0, 0.0, 0.0), inverted).level == 8192);
	CHECK(constant_effect_force_n(constant_effect(right), 4.0).x == doctest::Approx(1.0).epsilon(1e-4));
}

TEST_CASE("sdl effect: the constant effect is finite and renewed well before it ends, and the inverse recovers the force") {
	CHECK(SDL_EFFECT_LENGTH_MS != SDL_HAPTIC_INFINITY);
	CHECK(SDL_EFFECT_LENGTH_MS <= 0x7fff); // SDL's Linux driver clamps lengths to 32767 ms.
	CHECK(SDL_EFFECT_RENEW_S * 1000.0 * 3.0 <= SDL_EFFECT_LENGTH_MS);
	const SDL_HapticEffect effect = constant_effect(SdlConstantForce{ SDL_HAPTIC_POLAR, 13500, 20000 });
	CHECK(effect.type == SDL_HAPTIC_CONSTANT);
	CHECK(effect.constant.length == SDL_EFFECT_LENGTH_MS);
	CHECK(effect.constant.direction.type == SDL_HAPTIC_POLAR);
	CHECK(effect.constant.direction.dir[0] == 13500);
	CHECK(effect.constant.level == 20000);
	const SdlForceMapping mapping{ 5.0, false, false, false };
	const Vec3 force(1.3, -0.7, 0.0);
	const Vec3 back = constant_effect_force_n(constant_effect(map_force_to_sdl(force, mapping)), 5.0);
	CHECK(back.x == doctest::Approx(1.3).epsilon(1e-3));
	CHECK(back.y == doctest::Approx(-0.7).epsilon(1e-3));
}

TEST_CASE("sdl rumble envelope: small motor always, large above the knee, release and floor, 0x7FFF full") {
	const SdlRumbleMapping mapping;
	SdlRumbleEnvelope envelope;
	SdlRumbleLevels levels = envelope.update(1.5, 0.004, mapping);
	CHECK(levels.small == 16384);
	CHECK(levels.large == 0);
	levels = envelope.update(9.0, 0.004, mapping);
	CHECK(levels == SdlRumbleLevels{ 0x7fff, 0x7fff });
	levels = envelope.update(0.0, mapping.release_s, mapping);
	CHECK(envelope.level() == doctest::Approx(std::exp(-1.0)));
	CHECK(levels.large == 0);
	CHECK(envelope.update(0.0, 10 * mapping.release_s, mapping) == SdlRumbleLevels{});
	CHECK(envelope.update(std::nan(""), 0.004, mapping) == SdlRumbleLevels{});
	const SDL_HapticEffect effect = leftright_effect(SdlRumbleLevels{ 100, 200 });
	CHECK(effect.type == SDL_HAPTIC_LEFTRIGHT);
	CHECK(effect.leftright.large_magnitude == 100);
	CHECK(effect.leftright.small_magnitude == 200);
	CHECK(effect.leftright.length == SDL_EFFECT_LENGTH_MS);
}
