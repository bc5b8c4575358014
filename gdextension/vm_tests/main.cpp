// The test program tools/kernel/run.sh boots a VM for: runs the scenarios named on the command
// line (all without arguments) against the VM's real kernel and prints KTEST lines
// (ktest.h), then "KTEST-DONE failed=N". Exit status: the number of failed checks, capped.

#include "ktest.h"
#include "scenarios.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace {

struct Scenario {
	const char *name;
	int (*run)();
};

constexpr Scenario SCENARIOS[] = {
	{ "pid-hidraw", haptics::vm::run_pid_hidraw },
	{ "dualsense", haptics::vm::run_dualsense },
	{ "evdev-uinput", haptics::vm::run_evdev_uinput },
};

} // namespace

int main(int p_argc, char **p_argv) {
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
		failed += scenario.run();
		++ran;
	}
	std::printf("KTEST-DONE scenarios=%d failed=%d\n", ran, failed);
	std::fflush(stdout);
	return failed > 100 ? 100 : failed;
}
