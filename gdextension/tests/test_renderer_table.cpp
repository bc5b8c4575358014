// The renderer table as the engine and the binding walk it: one row per renderer in
// render-mode order, each naming its force components, raising telemetry flags of its own and
// holding its own settings value in the configuration.

#include "core/servo/telemetry.h"
#include "core/wire/codec.h"
#include "system/render_config.h"
#include "system/renderer_registry.h"
#include "system/settings_validation.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <vector>

using namespace haptics;

namespace {

std::vector<std::string> names_of(std::span<const char *const> p_names) {
	return std::vector<std::string>(p_names.begin(), p_names.end());
}

} // namespace

TEST_CASE("renderer table: a row per render mode, named as GDScript's constants") {
	const std::span<const RegisteredRenderer> rows = registered_renderers();
	REQUIRE(rows.size() == RENDER_MODE_COUNT);
	CHECK(std::string(rows[RenderMode::MOVEMENT].name) == "movement");
	CHECK(std::string(rows[RenderMode::CONSTRAINT].name) == "constraint");
	CHECK(std::string(rows[RenderMode::PONG].name) == "pong");
	CHECK(std::string(rows[RenderMode::VEHICLE].name) == "vehicle");
}

TEST_CASE("renderer table: each renderer names its own force components") {
	const std::span<const RegisteredRenderer> rows = registered_renderers();
	const std::vector<std::string> movement = { "normal", "friction", "weight", "drag", "inertia" };
	CHECK(names_of(rows[RenderMode::MOVEMENT].info->force_names) == movement);
	CHECK(names_of(rows[RenderMode::CONSTRAINT].info->force_names) == std::vector<std::string>{ "wall" });
	CHECK(names_of(rows[RenderMode::PONG].info->force_names) == std::vector<std::string>{ "contact", "spin", "effects" });
	CHECK(names_of(rows[RenderMode::VEHICLE].info->force_names) ==
			std::vector<std::string>{ "aligning", "damping", "texture" });
	for (const RegisteredRenderer &row : rows) {
		CAPTURE(row.name);
		CHECK(!row.info->force_names.empty());
		CHECK(row.info->force_names.size() <= MAX_FORCE_PARTS);
	}
}

TEST_CASE("renderer table: telemetry flags are each renderer's own bits, above the servo's") {
	std::set<uint32_t> bits;
	for (const uint32_t flag : servo_telemetry_flags()) {
		CHECK(flag < (1u << FIRST_RENDERER_FLAG_BIT));
		CHECK(bits.insert(flag).second);
	}
	for (const RegisteredRenderer &row : registered_renderers()) {
		for (const uint32_t flag : row.info->telemetry_flags) {
			CAPTURE(row.name);
			CHECK(flag >= (1u << FIRST_RENDERER_FLAG_BIT));
			CHECK(bits.insert(flag).second);
		}
	}
}

TEST_CASE("renderer table: each renderer's settings are its own value in the configuration") {
	RenderConfig config;
	config.pong.gravity_m_per_s2 = 4.0;
	config.servo.input.dead_zone = 0.1;
	config.movement.force_model.gravity_n_per_kg = 2.0;
	CHECK(validate_render_config(config));
	// A renderer's settings travel as its own schema value, whole.
	PongConfig pong;
	REQUIRE(decode(encode(config.pong), pong));
	CHECK(pong.gravity_m_per_s2 == 4.0);
	CHECK(std::string(PongConfig::NAME) == "PongSettings");
	CHECK(std::string(MovementConfig::NAME) == "HapticMovementSettings");
	CHECK(std::string(ConstraintConfig::NAME) == "HapticConstraintSettings");
	CHECK(std::string(VehicleConfig::NAME) == "HapticVehicleSettings");
}
