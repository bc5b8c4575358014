// The renderer interface seen from a renderer alone: what it receives, returns and keeps
// across new settings and reset().

#include "renderers/constraint/constraint_renderer.h"
#include "renderers/movement/force_model.h"
#include "renderers/movement/movement_renderer.h"

#include <doctest/doctest.h>

using namespace haptics;

namespace {

constexpr double DT = 0.001;

Frame floor_frame() {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	return frame;
}

RenderResult render_once(Renderer &r_renderer, const Frame &p_frame, const Vec3 &p_input) {
	const DeviceState device;
	RenderResult result;
	r_renderer.render(RenderInput{ device, p_input, p_frame, true, DT, 0.1, false }, result);
	return result;
}

// A renderer at the start of a session with p_config, as the servo starts one.
template <typename R>
void start(R &r_renderer, typename R::Channels &r_channels, const typename R::Config &p_config) {
	r_channels.settings.store(p_config);
	r_renderer.pick_up_settings(DT, true);
	r_renderer.begin_session(DT);
}

// The game changes p_config while rendering; the servo takes it at its next tick.
template <typename R>
void change(R &r_renderer, typename R::Channels &r_channels, const typename R::Config &p_config) {
	r_channels.settings.store(p_config);
	r_renderer.pick_up_settings(DT, false);
}

} // namespace

TEST_CASE("movement renderer: the model's components, and the continuous sum smoothed or not") {
	MovementChannels channels;
	MovementRenderer renderer(channels);
	MovementConfig config;
	config.smoothing.enabled = false;
	start(renderer, channels, config);
	const Frame frame = floor_frame();
	RenderResult result = render_once(renderer, frame, { 0.3, -0.5, 0.0 });
	CHECK(result.forces.parts[NORMAL_FORCE].y == doctest::Approx(1.0)); // -k p with the default k = 2.
	CHECK(result.forces.parts[FRICTION_FORCE].x == doctest::Approx(-0.3)); // -b r with b = 1.
	CHECK(result.continuous == result.forces.continuous);
	CHECK(result.flags == 0u);

	config.smoothing.enabled = true;
	change(renderer, channels, config);
	renderer.reset();
	result = render_once(renderer, frame, { 0.3, -0.5, 0.0 });
	CHECK(result.forces.parts[NORMAL_FORCE].y == doctest::Approx(1.0)); // Components stay raw...
	CHECK(result.continuous.y > 0.0);
	CHECK(result.continuous.y < 0.01); // ...the continuous force starts from rest.
}

TEST_CASE("movement renderer: writes every field it owns in place, over whatever was there") {
	MovementChannels channels;
	MovementRenderer renderer(channels);
	MovementConfig config;
	config.smoothing.enabled = false;
	start(renderer, channels, config);
	RenderResult result;
	result.forces.parts[WEIGHT_FORCE] = { 5.0, 5.0, 5.0 };
	result.forces.impact = { 7.0, 0.0, 0.0 }; // The pipeline's: left alone.
	result.flags = 99;
	Frame frame = floor_frame();
	const DeviceState device;
	renderer.render(RenderInput{ device, { 0.3, -0.5, 0.0 }, frame, true, DT, 0.1, false }, result);
	const MovementForces fresh = compute_forces(frame, { 0.3, -0.5, 0.0 }, config.force_model);
	CHECK(result.forces.parts[NORMAL_FORCE] == fresh.normal);
	CHECK(result.forces.parts[FRICTION_FORCE] == fresh.friction);
	CHECK(result.forces.parts[WEIGHT_FORCE] == Vec3{});
	CHECK(result.forces.continuous == fresh.continuous);
	CHECK(result.forces.impact == Vec3{ 7.0, 0.0, 0.0 });
	CHECK(result.flags == 0u);
}

TEST_CASE("movement renderer: a material change keeps the filter's motion, reset() does not") {
	MovementChannels channels;
	MovementRenderer renderer(channels);
	MovementConfig config;
	start(renderer, channels, config);
	const Frame frame = floor_frame();
	Vec3 before;
	for (int k = 0; k < 20; ++k) {
		before = render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous;
	}
	config.force_model.default_contact.friction_n = 0.5;
	change(renderer, channels, config);
	const Vec3 after = render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous;
	CHECK(after.y > before.y); // Still rising from where it was.
	renderer.reset();
	CHECK(render_once(renderer, frame, { 0.0, -0.5, 0.0 }).continuous.y < 0.01);
}

TEST_CASE("constraint renderer: takes the game's walls while inactive, and says what holds the proxy") {
	ConstraintChannels channels;
	ConstraintRenderer renderer(channels);
	ConstraintConfig config;
	config.proxy_radius = 5.0;
	start(renderer, channels, config);
	const Segment2 wall{ { 50.0, -100.0 }, { 50.0, 100.0 } };
	MazeMapping mapping;
	mapping.maze_min = { -100.0, -100.0 };
	mapping.maze_max = { 100.0, 100.0 };
	std::unique_ptr<ConstraintGeometry> geometry;
	REQUIRE(ConstraintGeometry::build(&wall, 1, mapping, BroadPhase::UNIFORM_GRID, geometry));
	channels.geometry.publish(std::move(geometry));
	renderer.pick_up();
	renderer.publish(ForceComponents{}, false);
	ProxyState state = channels.state.load();
	CHECK(state.geometry_segments == 1);
	CHECK(state.geometry_generation == 1);
	CHECK_FALSE(state.placed); // Not the active renderer: no proxy to show.

	DeviceState device;
	RenderResult result;
	result.forces.parts[WALL_FORCE + 2] = { 1.0, 2.0, 3.0 }; // Whatever was left there: every field is overwritten.
	renderer.render(RenderInput{ device, {}, Frame{}, true, DT, 0.1, false }, result);
	CHECK(result.forces.parts[WALL_FORCE + 2] == Vec3{});
	CHECK(result.flags == TELEMETRY_FLAG_CONSTRAINT_MODE);
	device.position_m = { 0.06, 0.0, 0.0 }; // Past the wall.
	renderer.render(RenderInput{ device, {}, Frame{}, false, DT, 0.1, false }, result);
	CHECK(result.forces.parts[WALL_FORCE].x < 0.0);
	CHECK(result.continuous == result.forces.parts[WALL_FORCE]); // Never filtered.
	CHECK(result.flags == (TELEMETRY_FLAG_CONSTRAINT_MODE | TELEMETRY_FLAG_PROXY_CONTACT));
	renderer.publish(result.forces, true);
	state = channels.state.load();
	CHECK(state.placed);
	CHECK(state.constraints == 1);
	CHECK(state.updates == 2);
	channels.collect();
}
