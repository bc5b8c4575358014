// The servo thread: start/stop (1 000 cycles), zero force written by the servo before it
// is joined, shutdown while rendering full force, unplugging while running, and the game
// thread using every channel concurrently. No timed assertion: waits poll with a generous
// time-out that only fails a hung test.

#include "core/servo/telemetry.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

using namespace haptics;

namespace {

// What a device saw, shared with the test so it survives the engine.
struct DeviceLog {
	std::atomic<uint64_t> writes{ 0 };
	std::atomic<double> last_magnitude{ 0.0 };
	std::atomic<double> peak_magnitude{ 0.0 };
	std::atomic<std::thread::id> last_writer{};
	std::atomic<bool> closed{ false };
	std::atomic<bool> written_after_close{ false };
	std::atomic<double> magnitude_at_close{ -1.0 };
};

// A simulated device that records every force written to it.
class RecordingDevice final : public HapticDevice {
public:
	RecordingDevice(std::shared_ptr<DeviceLog> p_log, const SimulatedDeviceConfig &p_config) :
			log_(std::move(p_log)), inner_(p_config) {}

	Status open() override { return inner_.open(); }
	void close() override {
		log_->magnitude_at_close.store(log_->last_magnitude.load());
		log_->closed.store(true);
		inner_.close();
	}
	bool is_open() const override { return inner_.is_open(); }
	Status calibrate() override { return inner_.calibrate(); }
	DeviceCapabilities capabilities() const override { return inner_.capabilities(); }
	const char *name() const override { return "recording device"; }
	void begin_tick(double p_dt_s) override { inner_.begin_tick(p_dt_s); }
	DeviceIo read_state(DeviceState &r_state) override { return inner_.read_state(r_state); }
	DeviceIo write_force(const ForceCommand &p_command) override {
		const Vec3 &p_force_n = p_command.force_n;
		if (log_->closed.load()) {
			log_->written_after_close.store(true);
		}
		const double magnitude = length(p_force_n);
		log_->last_magnitude.store(magnitude);
		log_->peak_magnitude.store(std::max(log_->peak_magnitude.load(), magnitude));
		log_->last_writer.store(std::this_thread::get_id());
		log_->writes.fetch_add(1);
		return inner_.write_force(p_command);
	}
	bool has_hand() const override { return true; }
	Status set_hand_target(const Vec3 &p_target_m) override { return inner_.set_hand_target(p_target_m); }
	SimulatedDevice &inner() { return inner_; }

private:
	std::shared_ptr<DeviceLog> log_;
	SimulatedDevice inner_;
};

template <typename Predicate>
bool wait_for(Predicate p_done, double p_timeout_s = 20.0) {
	const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_timeout_s);
	while (!p_done()) {
		if (std::chrono::steady_clock::now() > give_up) {
			return false;
		}
		std::this_thread::sleep_for(std::chrono::microseconds(200));
	}
	return true;
}

// Pressing hard into a wall: far beyond the 3.3 N limit, so output is at full force.
void render_full_force(HapticsSystem &r_system) {
	ForceModelConfig model;
	model.default_contact = ContactMaterial{ 20.0, 0.0 };
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.movement.force_model = model; }));
	SafetyConfig safety;
	safety.startup_ramp_s = 0.01;
	safety.watchdog_timeout_s = 10.0; // Frames are not resubmitted here.
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.servo.safety = safety; }));
	REQUIRE(r_system.set_hand_target({ 0.08, 0.0, 0.0 }));
	Frame wall;
	add_contact(wall, { -1.0, 0.0, 0.0 });
	REQUIRE(r_system.submit_frame(wall));
}

RecordingDevice *open_recording(HapticsSystem &r_system, const std::shared_ptr<DeviceLog> &p_log) {
	SimulatedDeviceConfig config;
	config.rigid_hand = true;
	auto device = std::make_unique<RecordingDevice>(p_log, config);
	RecordingDevice *raw = device.get();
	REQUIRE(r_system.open_device(std::move(device)));
	return raw;
}

} // namespace

TEST_CASE("servo thread: starts, ticks, reports its scheduler, stops") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(system.start(1000.0));
	CHECK(system.is_running());
	CHECK(system.start(1000.0).code() == StatusCode::INVALID_STATE);
	CHECK(system.step(0.001).code() == StatusCode::INVALID_STATE);
	CHECK(system.calibrate().code() == StatusCode::INVALID_STATE);
	REQUIRE(wait_for([&] { return system.stats().ticks >= 50; }));
	const ServoStats stats = system.stats();
	CHECK(stats.running);
	// On Windows an MMCSS task (realtime_windows.cpp), else normal.
	CHECK((stats.scheduler == SchedulerKind::REALTIME_FIFO || stats.scheduler == SchedulerKind::NORMAL ||
			stats.scheduler == SchedulerKind::MMCSS_PRO_AUDIO || stats.scheduler == SchedulerKind::MMCSS_GAMES));
	MESSAGE("servo scheduler: " << std::string(scheduler_kind_name(stats.scheduler)) << " priority " << stats.realtime_priority);
	CHECK(stats.nominal_rate_hz == 1000.0);
	CHECK(stats.achieved_rate_hz > 0.0);
	CHECK(stats.period_p50_s > 0.0);
	CHECK(stats.tick_cost_p50_s > 0.0);
	system.stop();
	CHECK_FALSE(system.is_running());
	CHECK(system.servo_status());
	system.stop(); // Idempotent.
}

TEST_CASE("servo thread: stop while rendering full force writes zero from the servo before the join") {
	auto log = std::make_shared<DeviceLog>();
	HapticsSystem system;
	open_recording(system, log);
	render_full_force(system);
	REQUIRE(system.start(1000.0));
	REQUIRE(wait_for([&] { return log->last_magnitude.load() > 3.2; }));
	system.stop();
	CHECK(log->last_magnitude.load() == 0.0);
	CHECK(log->last_writer.load() != std::this_thread::get_id()); // The servo wrote it.
	CHECK(log->peak_magnitude.load() == doctest::Approx(3.3));
	CHECK_FALSE(log->closed.load());
}

TEST_CASE("servo thread: destroying the engine mid-render zeroes the force, then closes") {
	auto log = std::make_shared<DeviceLog>();
	{
		HapticsSystem system;
		open_recording(system, log);
		render_full_force(system);
		REQUIRE(system.start(4000.0));
		REQUIRE(wait_for([&] { return log->last_magnitude.load() > 3.2; }));
	} // Scene change / quit.
	CHECK(log->closed.load());
	CHECK(log->magnitude_at_close.load() == 0.0);
	CHECK_FALSE(log->written_after_close.load());
}

TEST_CASE("servo thread: 1000 start/stop cycles while rendering, zero force after each") {
	auto log = std::make_shared<DeviceLog>();
	HapticsSystem system;
	open_recording(system, log);
	render_full_force(system);
	const double rates[] = { 250.0, 1000.0, 4000.0 };
	int start_failures = 0, hung = 0, nonzero_after_stop = 0, still_running = 0;
	for (int cycle = 0; cycle < 1000; ++cycle) {
		const uint64_t writes_before = log->writes.load();
		if (!system.start(rates[cycle % 3])) {
			++start_failures;
			continue;
		}
		// At least one tick plus the zero write; every other cycle also push an impact.
		if (cycle % 2 == 0) {
			ImpactEvent event;
			event.direction = { 0.0, 1.0, 0.0 };
			event.speed_m_per_s = 1.0;
			system.push_impact(event);
		}
		if (!wait_for([&] { return system.stats().ticks >= 1; })) {
			++hung;
		}
		system.stop();
		nonzero_after_stop += log->last_magnitude.load() != 0.0 ? 1 : 0;
		still_running += system.is_running() ? 1 : 0;
		if (log->writes.load() < writes_before + 2) {
			++hung;
		}
	}
	CHECK(start_failures == 0);
	CHECK(hung == 0);
	CHECK(nonzero_after_stop == 0);
	CHECK(still_running == 0);
	CHECK(system.servo_status());
}

TEST_CASE("servo thread: unplugging stops rendering with a clear error, state survives") {
	auto log = std::make_shared<DeviceLog>();
	HapticsSystem system;
	RecordingDevice *device = open_recording(system, log);
	render_full_force(system);
	const RenderConfig config_before = system.config();
	REQUIRE(system.start(1000.0));
	REQUIRE(wait_for([&] { return system.stats().ticks >= 20; }));
	device->inner().set_plugged(false);
	REQUIRE(wait_for([&] { return !system.is_running(); }));
	const Status status = system.servo_status();
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::strstr(status.message(), "recording device") != nullptr);
	CHECK(std::strstr(status.message(), "disconnected") != nullptr);
	CHECK(system.has_device());
	CHECK(std::memcmp(&system.config(), &config_before, sizeof(RenderConfig)) == 0);
	CHECK(system.stats().ticks >= 20); // Stats of the run are still readable.
	system.stop(); // Joins the ended thread; no hang, no crash.
	CHECK_FALSE(system.is_running());

	// Plugged back in, rendering can start again and the retained frame is felt.
	device->inner().set_plugged(true);
	CHECK(system.servo_status().code() == StatusCode::DEVICE_DISCONNECTED); // Until a new device.
	REQUIRE(system.open_device(std::make_unique<RecordingDevice>(log, SimulatedDeviceConfig{})));
	CHECK(system.servo_status());
	REQUIRE(system.set_hand_target({ 0.08, 0.0, 0.0 }));
	REQUIRE(system.start(1000.0));
	REQUIRE(wait_for([&] { return log->last_magnitude.load() > 1.0; }));
	system.stop();
	CHECK(log->last_magnitude.load() == 0.0);
}

TEST_CASE("servo thread: the game thread uses every channel while the servo runs") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(system.start(2000.0));
	std::vector<float> telemetry(256 * TELEMETRY_STRIDE);
	size_t drained = 0, non_finite = 0, time_went_back = 0;
	float last_time = -1.0f;
	for (int frame_index = 0; frame_index < 150; ++frame_index) {
		Frame frame;
		add_contact(frame, { std::cos(frame_index * 0.1), std::sin(frame_index * 0.1), 0.0 });
		add_resting(frame, { 0.0, -1.0, 0.0 }, 0.5);
		set_water(frame, frame_index % 2 == 0, 0.3, 0.2);
		frame.velocity_m_per_s = { 1.0, 0.0, 0.0 };
		REQUIRE(system.submit_frame(frame));
		REQUIRE(system.set_hand_target({ 0.0005 * (frame_index % 100), -0.02, 0.0 }));
		ImpactEvent event;
		event.direction = { 0.0, 1.0, 0.0 };
		event.speed_m_per_s = 2.0;
		REQUIRE(system.push_impact(event));
		SmoothingConfig smoothing;
		smoothing.cutoff_hz = 10.0 + frame_index % 5;
		REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.movement.smoothing = smoothing; }));
		non_finite += is_finite(system.forces().total) ? 0 : 1;
		non_finite += is_finite(system.input_vector()) ? 0 : 1;
		(void)system.stats();
		const size_t count = system.drain_telemetry(telemetry.data(), 256);
		for (size_t s = 0; s < count; ++s) {
			const float *sample = telemetry.data() + s * TELEMETRY_STRIDE;
			for (size_t c = 0; c < TELEMETRY_STRIDE; ++c) {
				non_finite += std::isfinite(sample[c]) ? 0 : 1;
			}
			time_went_back += sample[TELEMETRY_TIME] <= last_time ? 1 : 0;
			last_time = sample[TELEMETRY_TIME];
		}
		drained += count;
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	REQUIRE(wait_for([&] { return system.stats().frames_received >= 1; }));
	system.stop();
	CHECK(non_finite == 0);
	CHECK(time_went_back == 0);
	CHECK(drained > 0);
	const ServoStats stats = system.stats();
	CHECK(stats.non_finite_ticks == 0);
	CHECK(length(system.forces().total) <= 3.3 + 1e-9);
}
