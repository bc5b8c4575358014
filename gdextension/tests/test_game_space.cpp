// A 3D game's values (their 3D forms, GameSpace::SPACE): the wire keeps their depth, and the
// servo knows from the frame that the game is 3D: no plane hold on a 3-DOF device, and a
// 2-axis stick on the ground plane (forward is into the screen), forces mapped back onto it.

#include "core/wire/codec.h"
#include "devices/simulated_device.h"
#include "renderers/movement/force_model.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cstring>
#include <memory>

using namespace haptics;

namespace {

constexpr double DT = 0.001;

uint32_t layout_of(const std::vector<uint8_t> &p_bytes) {
	uint32_t id = 0;
	std::memcpy(&id, p_bytes.data(), sizeof(id));
	return id;
}

Frame wall_in_front() {
	Frame frame;
	add_contact(frame, { 0.0, 0.0, 1.0 }); // Faces the viewer.
	return frame;
}

// A 2-axis stick: the simulated device's x and y, its force as last written.
class Stick final : public HapticDevice {
public:
	explicit Stick(const SimulatedDeviceConfig &p_config) :
			inner_(p_config) {}

	Status open() override { return inner_.open(); }
	void close() override { inner_.close(); }
	bool is_open() const override { return inner_.is_open(); }
	Status calibrate() override { return inner_.calibrate(); }
	DeviceCapabilities capabilities() const override {
		DeviceCapabilities caps = inner_.capabilities();
		caps.input_dof = 2;
		caps.output_dof = 2;
		return caps;
	}
	const char *name() const override { return "test stick"; }
	void begin_tick(double p_dt_s) override { inner_.begin_tick(p_dt_s); }
	DeviceIo read_state(DeviceState &r_state) override {
		const DeviceIo io = inner_.read_state(r_state);
		r_state.position_m.z = 0.0;
		return io;
	}
	DeviceIo write_force(const ForceCommand &p_command) override {
		written = p_command.force_n;
		return inner_.write_force(ForceCommand{ {}, {} });
	}
	bool has_hand() const override { return true; }
	Status set_hand_target(const Vec3 &p_target_m) override { return inner_.set_hand_target(p_target_m); }

	Vec3 written;

private:
	SimulatedDevice inner_;
};

void exact(HapticsSystem &r_system) {
	REQUIRE(reconfigure(r_system, [](RenderConfig &c) {
		c.movement.force_model = ForceModelConfig{};
		c.movement.smoothing = SmoothingConfig{ false, 13.0 };
		c.servo.input.dead_zone = 0.0;
		c.servo.safety.startup_ramp_s = 0.0;
		c.servo.safety.slew_rate_n_per_s = 0.0;
	}));
}

} // namespace

TEST_CASE("game space: a frame's 3D form keeps depth, says so, and is refused nowhere else") {
	Frame frame = wall_in_front();
	frame.velocity_m_per_s = { 0.5, -1.0, 2.0 };
	const std::vector<uint8_t> bytes = encode(frame, GameSpace::SPACE);
	CHECK(layout_of(bytes) == Frame::SCHEMA_ID_3D);
	Frame back;
	GameSpace space = GameSpace::PLANE;
	REQUIRE(decode(bytes, back, &space));
	CHECK(space == GameSpace::SPACE);
	CHECK(back.contacts[0].normal.z == 1.0);
	CHECK(back.velocity_m_per_s.y == -1.0); // Up is up: no flip in 3D.
	CHECK(back.velocity_m_per_s.z == 2.0);

	// The 2D form loses depth and flips y, as a 2D game reads it (and the wall in front,
	// straight along depth, would have no direction left in it).
	frame.contacts.clear();
	const std::vector<uint8_t> flat = encode(frame);
	CHECK(layout_of(flat) == Frame::SCHEMA_ID);
	REQUIRE(decode(flat, back, &space));
	CHECK(space == GameSpace::PLANE);
	CHECK(back.velocity_m_per_s.z == 0.0);
	CHECK(back.velocity_m_per_s.y == -1.0);

	// A 3D frame's bytes are no impact, and a value without a 3D form writes its only one.
	ImpactEvent impact;
	CHECK_FALSE(decode(bytes, impact));
	CHECK(layout_of(encode(ContactMaterial{}, GameSpace::SPACE)) == ContactMaterial::SCHEMA_ID);
}

TEST_CASE("game space: a 3D frame's limits are checked in 3D, a zero normal refused with the frame") {
	Frame frame;
	add_contact(frame, { 0.0, 0.0, 0.0 });
	HapticsSystem system;
	CHECK_FALSE(system.submit_frame(frame, GameSpace::SPACE));
	CHECK(system.stats().frames_rejected == 1);
	// Straight toward the viewer: a direction in 3D (in 2D it would have no length).
	CHECK(system.submit_frame(wall_in_front(), GameSpace::SPACE));
}

TEST_CASE("game space: a 3-DOF device pressing into a wall in front feels it along depth, with no plane hold") {
	HapticsSystem system;
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(system.open_simulated_device(device));
	exact(system);
	REQUIRE(system.set_hand_target({ 0.0, 0.0, -0.05 })); // Pushed forward, half the radius.

	// In a 2D game the plane hold pulls the stylus back to the screen's plane.
	REQUIRE(system.submit_frame(Frame{}));
	REQUIRE(system.step(DT));
	CHECK(system.forces().total.z > 1.0);

	// In a 3D game depth is the game's own: an empty frame renders nothing, a wall k i.
	REQUIRE(system.submit_frame(Frame{}, GameSpace::SPACE));
	REQUIRE(system.step(DT));
	CHECK(system.forces().total.z == doctest::Approx(0.0));
	REQUIRE(system.submit_frame(wall_in_front(), GameSpace::SPACE));
	REQUIRE(system.step(DT));
	CHECK(system.input_vector().z == doctest::Approx(-0.5));
	CHECK(system.forces().total.z == doctest::Approx(1.0)); // k = 2 times 0.5.
	CHECK(system.forces().total.x == doctest::Approx(0.0));
}

TEST_CASE("game space: a 2-axis stick in a 3D game works the ground plane, both ways") {
	HapticsSystem system;
	SimulatedDeviceConfig config;
	config.rigid_hand = true;
	auto owned = std::make_unique<Stick>(config);
	Stick *stick = owned.get();
	REQUIRE(system.open_device(std::move(owned)));
	exact(system);
	REQUIRE(system.set_hand_target({ 0.02, 0.05, 0.0 })); // Right a little, forward half.

	REQUIRE(system.submit_frame(wall_in_front(), GameSpace::SPACE));
	REQUIRE(system.step(DT));
	// Forward on the stick is into the screen.
	CHECK(system.input_vector().x == doctest::Approx(0.2));
	CHECK(system.input_vector().y == doctest::Approx(0.0));
	CHECK(system.input_vector().z == doctest::Approx(-0.5));
	// The wall pushes back toward the viewer (+z): on the stick, backward (-y). Friction
	// resists the slide to the right.
	CHECK(system.forces().total.z == doctest::Approx(1.0));
	CHECK(stick->written.y == doctest::Approx(-1.0));
	CHECK(stick->written.x == doctest::Approx(system.forces().total.x));
	CHECK(stick->written.x < 0.0);
	CHECK(stick->written.z == 0.0);

	// A 2D game's frame: the stick is the screen's plane again, y up.
	REQUIRE(system.submit_frame(Frame{}));
	REQUIRE(system.step(DT));
	CHECK(system.input_vector().y == doctest::Approx(0.5));
	CHECK(system.input_vector().z == doctest::Approx(0.0));
}
