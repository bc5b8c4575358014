// The test program tools/kernel/run.sh boots a VM for: runs the scenarios named on the command
// line (all without arguments) against the VM's real kernel and prints KTEST lines
// (ktest.h), then "KTEST-DONE failed=N". Exit status: the number of failed checks, capped.
// With GODOT_SDL_ARG first it is instead the Godot-like SDL process of sdl_godot.h.

#include "ktest.h"
#include "scenarios.h"
#if HAPTICS_SDL3
#include "sdl_godot.h"
#endif

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

namespace {

struct Scenario {
	const char *name;
	int (*run)();
};

constexpr Scenario SCENARIOS[] = {
	{ "pid-hidraw", haptics::vm::run_pid_hidraw },
	{ "pid-usb", haptics::vm::run_pid_usb },
	{ "falcon-usb", haptics::vm::run_falcon_usb },
	{ "dualsense", haptics::vm::run_dualsense },
	{ "evdev-uinput", haptics::vm::run_evdev_uinput },
#if HAPTICS_SDL3
	{ "sdl", haptics::vm::run_sdl },
	{ "godot-sdl-dualsense", haptics::vm::run_godot_sdl_dualsense },
	{ "godot-sdl-wheel", haptics::vm::run_godot_sdl_wheel },
#endif
};

// A scenario that hangs (a transfer nobody completes) must still leave the kernel's log and
// the other results readable: past this, the program says which one and exits.
constexpr auto SCENARIO_LIMIT = std::chrono::seconds(90);

class Watchdog {
public:
	explicit Watchdog(const char *p_scenario) :
			thread_([this, p_scenario] {
				std::unique_lock lock(mutex_);
				if (!done_changed_.wait_for(lock, SCENARIO_LIMIT, [this] { return done_; })) {
					std::printf("KTEST %s FAIL did not finish within %lld s\n", p_scenario,
							static_cast<long long>(SCENARIO_LIMIT.count()));
					std::fflush(stdout);
					std::_Exit(101);
				}
			}) {}
	~Watchdog() {
		{
			std::lock_guard lock(mutex_);
			done_ = true;
		}
		done_changed_.notify_one();
		thread_.join();
	}

private:
	std::mutex mutex_;
	std::condition_variable done_changed_;
	bool done_ = false;
	std::thread thread_;
};

} // namespace

int main(int p_argc, char **p_argv) {
#if HAPTICS_SDL3
	if (p_argc > 1 && std::strcmp(p_argv[1], haptics::vm::GODOT_SDL_ARG) == 0) {
		return haptics::vm::run_godot_sdl(p_argc - 2, p_argv + 2);
	}
#endif
	int failed = 0;
	int ran = 0;
	for (const Scenario &scenario : SCENARIOS) {
		bool wanted = p_argc < 2;
		for (int i = 1; i < p_argc; ++i) {
			wanted = wanted || std::strcmp(p_argv[i], scenario.name) == 0;
		}
		if (!wanted) {
			continue;
		}
		std::printf("KTEST-BEGIN %s\n", scenario.name);
		std::fflush(stdout);
		const Watchdog watchdog(scenario.name);
		failed += scenario.run();
		++ran;
	}
	std::printf("KTEST-DONE scenarios=%d failed=%d\n", ran, failed);
	std::fflush(stdout);
	return failed > 100 ? 100 : failed;
}
