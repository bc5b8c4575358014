// The hand-over between the servo and a device's own I/O thread (device_exchange.h,
// device_io_thread.h), through a loopback device whose "bus" is a counter, and the common
// backend soak run on it (so the harness every backend uses is itself tested).

#include "devices/backend_soak.h"
#include "devices/device_exchange.h"
#include "devices/device_io_thread.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>

namespace haptics {

namespace {

// A device whose I/O thread "transfers" by copying the command into a register and
// reporting a fixed position; it can be unplugged like a USB device.
class LoopbackDevice final : public HapticDevice, private DeviceIoWorker {
public:
	struct Wire {
		std::atomic<uint64_t> transfers{ 0 };
		std::atomic<double> last_force_y{ -1.0 };
		std::atomic<bool> plugged{ true };
		std::atomic<bool> zero_on_stop{ false };
	};

	LoopbackDevice(Wire &r_wire, double p_rate_hz) :
			wire_(r_wire), rate_hz_(p_rate_hz) {}
	~LoopbackDevice() override { close(); }

	Status open() override {
		if (!wire_.plugged.load()) {
			return Status::error(StatusCode::DEVICE_DISCONNECTED, "loopback: unplugged");
		}
		DeviceState initial;
		initial.position_m = { 0.0, -0.02, 0.0 }; // Presses into a floor.
		exchange_.reset(initial);
		open_ = thread_.start(*this, exchange_, DeviceIoThreadOptions{ rate_hz_, 0 }).ok();
		return open_ ? Status::success() : Status::error(StatusCode::DEVICE_ERROR, "loopback: no thread");
	}
	void close() override {
		thread_.stop();
		open_ = false;
	}
	bool is_open() const override { return open_; }
	Status calibrate() override { return Status::success(); }
	DeviceCapabilities capabilities() const override {
		DeviceCapabilities capabilities;
		capabilities.limits = { 3.0, 1.0, 500.0, 0.05 };
		capabilities.native_rate_hz = rate_hz_;
		return capabilities;
	}
	const char *name() const override { return "loopback"; }
	DeviceStatus status() const override { return exchange_.status(); }
	DeviceIo read_state(DeviceState &r_state) override { return exchange_.read_state(r_state); }
	DeviceIo write_force(const ForceCommand &p_command) override { return exchange_.write_command(p_command); }

	DeviceIoStats io_stats() const { return exchange_.stats(); }

private:
	DeviceIo io_cycle(DeviceExchange &r_exchange, double) override {
		if (!wire_.plugged.load()) {
			r_exchange.fail(DeviceIo::DISCONNECTED, "loopback cable pulled");
			return DeviceIo::DISCONNECTED;
		}
		const ForceCommand command = r_exchange.latest_command();
		wire_.last_force_y.store(command.force_n.y);
		wire_.transfers.fetch_add(1);
		DeviceState state;
		state.position_m = { 0.0, -0.02, 0.0 };
		r_exchange.publish_state(state);
		return DeviceIo::OK;
	}
	void io_stop() override {
		wire_.last_force_y.store(0.0);
		wire_.zero_on_stop.store(true);
	}

	Wire &wire_;
	double rate_hz_;
	DeviceExchange exchange_;
	DeviceIoThread thread_;
	bool open_ = false;
};

} // namespace

TEST_CASE("device exchange: the servo reads the latest state and the I/O side the latest command") {
	DeviceExchange exchange;
	DeviceState initial;
	initial.position_m = { 0.01, 0.02, 0.03 };
	exchange.reset(initial);
	DeviceState read;
	REQUIRE(exchange.read_state(read) == DeviceIo::OK);
	CHECK(read.position_m.y == doctest::Approx(0.02));

	CHECK(exchange.latest_command().force_n.x == 0.0); // Nothing written yet: zero.
	REQUIRE(exchange.write_command(ForceCommand{ { 1.0, 0.0, 0.0 }, {} }) == DeviceIo::OK);
	REQUIRE(exchange.write_command(ForceCommand{ { 2.0, 0.0, 0.0 }, {} }) == DeviceIo::OK);
	CHECK(exchange.latest_command().force_n.x == doctest::Approx(2.0)); // Latest, not a queue.
	CHECK(exchange.stats().commands_sent == 1);

	DeviceState next;
	next.position_m = { -0.01, 0.0, 0.0 };
	exchange.publish_state(next);
	REQUIRE(exchange.read_state(read) == DeviceIo::OK);
	CHECK(read.position_m.x == doctest::Approx(-0.01));
}

TEST_CASE("device exchange: a fault on the I/O side stops the servo side with its reason") {
	DeviceExchange exchange;
	exchange.reset();
	exchange.fail(DeviceIo::DISCONNECTED, "transfer failed: %s", "LIBUSB_ERROR_NO_DEVICE");
	DeviceState state;
	CHECK(exchange.read_state(state) == DeviceIo::DISCONNECTED);
	CHECK(exchange.write_command(ForceCommand{}) == DeviceIo::DISCONNECTED);
	const DeviceStatus status = exchange.status();
	CHECK(status.io == DeviceIo::DISCONNECTED);
	CHECK(std::strcmp(status.reason, "transfer failed: LIBUSB_ERROR_NO_DEVICE") == 0);

	exchange.reset(); // A reopen starts healthy.
	CHECK(exchange.read_state(state) == DeviceIo::OK);
	CHECK(exchange.status().reason[0] == '\0');
}

TEST_CASE("device exchange: a transfer stuck past OUTPUT_STALL_S shows in the status until it ends") {
	DeviceExchange exchange;
	exchange.reset();
	const int64_t began_ns = 5'000'000'000;
	const int64_t stall_ns = static_cast<int64_t>(OUTPUT_STALL_S * 1e9);
	exchange.begin_transfer(began_ns);
	DeviceStatus status = exchange.status(began_ns + stall_ns - 1'000'000);
	CHECK(status.output_stuck_s == 0.0); // A slow transfer is not yet an outage.
	CHECK(status.reason[0] == '\0');
	status = exchange.status(began_ns + 1'500'000'000); // A 1.5 s NAK.
	CHECK(status.io == DeviceIo::OK); // The servo goes on: the device holds its last force.
	CHECK(status.output_stuck_s == doctest::Approx(1.5));
	CHECK(std::strstr(status.reason, "no output for 1.50 s") != nullptr);
	exchange.end_transfer();
	status = exchange.status(began_ns + 1'600'000'000);
	CHECK(status.output_stuck_s == 0.0); // The wire moves again: clear.
	CHECK(status.reason[0] == '\0');
	exchange.begin_transfer(began_ns);
	exchange.fail(DeviceIo::FAILED, "write failed: EPIPE");
	status = exchange.status(began_ns + 1'000'000'000);
	CHECK(status.output_stuck_s == 0.0); // A fault says its own reason.
	CHECK(std::strcmp(status.reason, "write failed: EPIPE") == 0);
}

TEST_CASE("device io thread: a write that blocks is reported while it blocks, and the report clears") {
	DeviceExchange exchange;
	exchange.reset();
	DeviceIoThread thread;
	struct Worker final : DeviceIoWorker {
		std::atomic<bool> block{ false };
		std::atomic<bool> blocking{ false };
		DeviceIo io_cycle(DeviceExchange &, double) override {
			while (block.load()) {
				blocking.store(true);
				std::this_thread::sleep_for(std::chrono::milliseconds(1));
			}
			blocking.store(false);
			return DeviceIo::OK;
		}
	} worker;
	REQUIRE(thread.start(worker, exchange, DeviceIoThreadOptions{ 1000.0, 0 }));
	worker.block.store(true);
	// Generous bounds: a loaded machine may take long to schedule the thread.
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
	while (exchange.status().output_stuck_s == 0.0 && std::chrono::steady_clock::now() < deadline) {
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	CHECK(worker.blocking.load());
	CHECK(exchange.status().output_stuck_s > OUTPUT_STALL_S);
	worker.block.store(false);
	while (worker.blocking.load() && std::chrono::steady_clock::now() < deadline) {
		std::this_thread::sleep_for(std::chrono::milliseconds(2));
	}
	std::this_thread::sleep_for(std::chrono::milliseconds(20)); // Past the end of that cycle.
	CHECK(exchange.status().output_stuck_s == 0.0);
	thread.stop();
}

TEST_CASE("device io thread: rejects a bad rate and runs the worker until stopped, then io_stop") {
	LoopbackDevice::Wire wire;
	DeviceExchange exchange;
	DeviceIoThread thread;
	struct Worker final : DeviceIoWorker {
		std::atomic<int> cycles{ 0 };
		std::atomic<bool> stopped{ false };
		DeviceIo io_cycle(DeviceExchange &, double) override {
			cycles.fetch_add(1);
			return DeviceIo::OK;
		}
		void io_stop() override { stopped.store(true); }
	} worker;
	CHECK(thread.start(worker, exchange, DeviceIoThreadOptions{ 0.0, 0 }).code() == StatusCode::OUT_OF_RANGE);
	CHECK(thread.start(worker, exchange, DeviceIoThreadOptions{ 1e9, 0 }).code() == StatusCode::OUT_OF_RANGE);
	REQUIRE(thread.start(worker, exchange, DeviceIoThreadOptions{ 500.0, 0 }));
	while (worker.cycles.load() < 5) {
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
	thread.stop();
	CHECK(worker.stopped.load());
	CHECK_FALSE(thread.is_running());
	thread.stop(); // Idempotent.
}

TEST_CASE("device io thread: a 250 Hz device under the 1 kHz servo gets the latest force - the servo never waits") {
	LoopbackDevice::Wire wire;
	HapticsSystem system;
	test::BackendSoakScript script;
	script.make_device = [&] { return std::make_unique<LoopbackDevice>(wire, 250.0); };
	script.unplug = [&] { wire.plugged.store(false); };
	script.replug = [&] { wire.plugged.store(true); };
	const test::BackendSoakResult result = test::run_backend_soak(system, script);

	REQUIRE(result.opened_first);
	REQUIRE(result.opened_again);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::strcmp(result.device_status_after_unplug.reason, "loopback cable pulled") == 0);
	// Generous: a loaded 2-core machine still ticks most periods.
	CHECK(static_cast<double>(result.ticks_second) >= 0.6 * 1000.0 * result.seconds_second);
	CHECK(result.peak_total_force_n > 0.1); // The floor pushed back through the exchange.
	CHECK(wire.zero_on_stop.load()); // Closing wrote zero on the I/O thread.
	CHECK(wire.last_force_y.load() == 0.0);
	// The hand-over's latency: how old the servo's force is when the device takes it. At
	// 250 Hz it is at most one device period plus scheduling; never a queue of stale forces.
	const ServoStats &stats = result.stats_second;
	CHECK(stats.device_io_cycles > 0);
	CHECK(stats.device_command_age_mean_s < 0.5); // Generous: a loaded CI machine.
	MESSAGE("loopback soak: ", result.ticks_first, " + ", result.ticks_second, " ticks, ", wire.transfers.load(),
			" transfers at 250 Hz; command age mean ", stats.device_command_age_mean_s * 1e6, " us, max ",
			stats.device_command_age_max_s * 1e6, " us");
}

} // namespace haptics
