// The common backend soak (backend_soak.h) through HdDevice and the fake libHD: the 1 kHz
// servo renders a floor contact while HD's (fake) scheduler runs our callback at 1 kHz;
// "unplug" makes every frame end in HD_COMM_ERROR, the servo must stop itself with
// DEVICE_DISCONNECTED and the HD reason; "replug" clears it, the engine reopens (the new
// device pre-empts the old one's HD session) and renders again. Then the fake's record:
// forces set per second, the floor's force pointing up, zero as the last force before each
// hdDisableDevice, and no misuse of the API.

#include "backend_soak.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "openhaptics_fake.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::openhaptics;
using haptics::test::FakeHd;
using haptics::test::fresh_fake_hd;

TEST_CASE("openhaptics: backend soak through the servo: render, unplug (HD_COMM_ERROR), replug, render") {
	FakeHd &fake = fresh_fake_hd();
	// The stylus 20 mm below the workspace centre (0, 10, 10) mm: inside the floor.
	const double below_mm[3] = { 0.0, -10.0, 10.0 };
	fake.set_doubles(HD_CURRENT_POSITION, below_mm, 3);

	HapticsSystem system;
	haptics::test::BackendSoakScript script;
	script.make_device = [] { return make_device_on_runtime(haptics::test::fake_hd_path()); };
	script.unplug = [&fake] { fake.set_unplugged(1); };
	script.replug = [&fake] { fake.set_unplugged(0); };
	const unsigned long long ticks_before = fake.ticks();
	const haptics::test::BackendSoakResult result = haptics::test::run_backend_soak(system, script);
	const unsigned long long hd_ticks = fake.ticks() - ticks_before;

	REQUIRE(result.opened_first);
	CHECK(result.stopped_on_unplug);
	CHECK(result.status_after_unplug == StatusCode::DEVICE_DISCONNECTED);
	CHECK(result.device_status_after_unplug.io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(result.device_status_after_unplug.reason, "HD_COMM_ERROR") != nullptr);
	REQUIRE(result.opened_again);
	// Generous: a loaded 2-core machine still renders most ticks.
	CHECK(static_cast<double>(result.ticks_first) >= 0.6 * result.seconds_first * 1000.0);
	CHECK(static_cast<double>(result.ticks_second) >= 0.6 * result.seconds_second * 1000.0);
	CHECK(result.peak_total_force_n > 0.1);

	// The fake's record.
	const std::vector<FakeHdCall> calls = fake.calls();
	const double seconds = result.seconds_first + result.seconds_second;
	size_t force_sets = 0;
	size_t forces_outside_frames = 0;
	double max_up_n = 0.0;
	size_t disables = 0;
	size_t disables_after_zero = 0;
	const FakeHdCall *last_force = nullptr;
	for (const FakeHdCall &call : calls) {
		if (std::strcmp(call.name, "hdSetDoublev") == 0 && call.pname == HD_CURRENT_FORCE) {
			++force_sets;
			last_force = &call;
			max_up_n = std::max(max_up_n, call.values[1]);
			forces_outside_frames += call.in_frame ? 0 : 1;
		}
		if (std::strcmp(call.name, "hdDisableDevice") == 0) {
			++disables;
			const bool zero = last_force != nullptr && last_force->values[0] == 0.0 && last_force->values[1] == 0.0 &&
					last_force->values[2] == 0.0;
			disables_after_zero += zero ? 1 : 0;
		}
	}
	MESSAGE("openhaptics soak: ", result.ticks_first, " + ", result.ticks_second, " servo ticks in ",
			result.seconds_first, " + ", result.seconds_second, " s; HD callbacks ", hd_ticks, " (",
			static_cast<double>(hd_ticks) / seconds, "/s); HD_CURRENT_FORCE sets ", force_sets, " (",
			static_cast<double>(force_sets) / seconds, "/s); peak up force ", max_up_n, " N");
	CHECK(static_cast<double>(force_sets) >= 0.6 * seconds * 1000.0);
	CHECK(forces_outside_frames == 0);
	CHECK(max_up_n > 0.1); // The floor pushes the stylus up (+y, docs/devices/openhaptics.md).
	CHECK(max_up_n <= 0.88 + 1e-9); // Continuous: capped at HD_NOMINAL_MAX_CONTINUOUS_FORCE.
	CHECK(disables == 2); // The unplugged session and the second one.
	CHECK(disables_after_zero == disables);
	CHECK_FALSE(fake.scheduler_running());
	CHECK(fake.misuse_count() == 0);
	if (fake.misuse_count() != 0) {
		MESSAGE(fake.first_misuse());
	}
}
