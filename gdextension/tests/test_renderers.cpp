// The renderer interface seen from a renderer alone: what it receives, returns and keeps
// across configure() and reset().

#include "core/constraint_renderer.h"
#include "core/geometry_exchange.h"
#include "core/movement_renderer.h"
#include "core/telemetry.h"

#include <doctest/doctest.h>

using namespace haptics;

namespace {

constexpr double DT = 0.001;

Frame floor_frame() {
	Frame frame;
	frame.add_contact({ 0.0, 1.0, 0.0 });
	return frame;
}

RenderResult render_once(Renderer &r_renderer, const Frame &p_frame, const Vec3 &p_input) {
	const DeviceState device;
	RenderResult result;
	r_renderer.render(RenderInput{ device, p_input, p_frame, true, DT, 0.1, false }, result);
	return result;
}

// A renderer at the start of a session with p_config.
void start(Renderer &r_renderer, const RenderConfig &p_config) {
	r_renderer.begin_session(DT);
	r_renderer.configure(p_config, DT);
}

} // namespace

TEST_CASE("movement renderer: the model's components, and the continuous sum smoothed or not") {
	MovementRenderer renderer;
	RenderConfig config;
	config.smoothing.enabled = false;
	start(renderer, config);
	const Frame frame = floor_frame();
	RenderResult result = render_once(renderer, frame, { 0.3, -0.5, 0.0 });
	CHECK(result.forces.normal.y == doctest::Approx(1.0)); // -k p with the default k = 2.
	CHECK(result.forces.friction.x == doctest::Approx(-0.3)); // -b r with b = 1.
	CHECK(result.continuous == result.forces.continuous);
	CHECK(result.flags == 0u);

	config.smoothing.enabled = true;
	renderer.configure(config, DT);
	renderer.reset();
	result = render_once(renderer, frame, { 0.3, -0.5, 0.0 });
	CHECK(result.forces.normal.y == doctest::Approx(1.0)); // Components stay raw...
	CHECK(result.continuous.y > 0.0);
	CHECK(result.continuous.y < 0.01); // ...the continuous force starts from rest.
}

TEST_CASE("movement renderer: writes every field it owns in place, over whatever was there") {
	MovementRenderer renderer;
	RenderConfig config;
	config.smoothing.enabled = false;
	start(renderer, config);
	RenderResult result;
	result.forces.weight = { 5.0, 5.0, 5.0 };
	result.forces.impact = { 7.0, 0.0, 0.0 }; // The pipeline's: left alone.
	result.flags = 99;
	Frame frame = floor_frame();
	const DeviceState device;
	renderer.render(RenderInput{ device, { 0.3, -0.5, 0.0 }, frame, true, DT, 0.1, false }, result);
	const ForceComponents fresh = compute_forces(frame, { 0.3, -0.5, 0.0 }, config.force_model);
	CHECK(result.forces.normal == fresh.normal);
	CHECK(result.forces.friction == fresh.friction);
	CHECK(result.forces.weight == Vec3{});
	CHECK(result.forces.continuous == fresh.continuous);
	CHECK(result.forces.impact == Vec3{ 7.0, 0.0, 0.0 });
	CHECK(result.flags == 0u);
}

TEST_CASE("movement renderer: a material change keeps the filter's motion, reset() does not") {
	MovementRenderer renderer;
	RenderConfig config;
	start(renderer, config);
	const Frame frame = floor_frame();
	Vec3 before;
	for (int k = 0; k < 20; ++k) {
		before = render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous;
	}
	config.force_model.default_contact.friction = 0.5;
	renderer.configure(config, DT);
	const Vec3 after = render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous;
	CHECK(after.y > before.y); // Still rising from where it was.
	renderer.reset();
	CHECK(render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous.y < 0.01);
}

TEST_CASE("constraint renderer: takes the game's walls while inactive, and says what holds the proxy") {
	GeometryExchange exchange;
	ConstraintRenderer renderer(exchange);
	RenderConfig config;
	config.constraint.proxy_radius = 5.0;
	start(renderer, config);
	const Segment2 wall{ { 50.0, -100.0 }, { 50.0, 100.0 } };
	MazeMapping mapping;
	mapping.maze_min = { -100.0, -100.0 };
	mapping.maze_max = { 100.0, 100.0 };
	std::unique_ptr<ConstraintGeometry> geometry;
	REQUIRE(ConstraintGeometry::build(&wall, 1, mapping, BroadPhase::UNIFORM_GRID, geometry));
	exchange.publish(std::move(geometry));
	renderer.pick_up();
	ServoOutput output;
	renderer.publish(output, false);
	CHECK(output.geometry_segments == 1);
	CHECK(output.geometry_generation == 1);
	CHECK_FALSE(output.proxy_placed); // Not the active renderer: no proxy to show.

	DeviceState device;
	RenderResult result;
	result.forces.weight = { 1.0, 2.0, 3.0 }; // Whatever was left there: every field is overwritten.
	renderer.render(RenderInput{ device, {}, Frame{}, true, DT, 0.1, false }, result);
	CHECK(result.forces.weight == Vec3{});
	CHECK(result.flags == TELEMETRY_FLAG_CONSTRAINT_MODE);
	device.position_m = { 0.06, 0.0, 0.0 }; // Past the wall.
	renderer.render(RenderInput{ device, {}, Frame{}, false, DT, 0.1, false }, result);
	CHECK(result.forces.normal.x < 0.0);
	CHECK(result.continuous == result.forces.normal); // Never filtered.
	CHECK(result.flags == (TELEMETRY_FLAG_CONSTRAINT_MODE | TELEMETRY_FLAG_PROXY_CONTACT));
	renderer.publish(output, true);
	CHECK(output.proxy_placed);
	CHECK(output.proxy_constraints == 1);
	CHECK(output.proxy_updates == 2);
	exchange.collect();
}
