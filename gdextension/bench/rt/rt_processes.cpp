#include "rt_processes.h"

#include "core/base/realtime.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace haptics::bench {

namespace {

constexpr double GRACE_S = 5.0;

std::vector<char *> c_argv(const std::vector<std::string> &p_argv) {
	std::vector<char *> argv;
	for (const std::string &arg : p_argv) {
		argv.push_back(const_cast<char *>(arg.c_str()));
	}
	argv.push_back(nullptr);
	return argv;
}

// Waits up to p_timeout_s for p_pid; true when it exited (status in r_status).
bool wait_for_exit(pid_t p_pid, double p_timeout_s, int &r_status) {
	const int64_t give_up = monotonic_now_ns() + static_cast<int64_t>(p_timeout_s * 1e9);
	while (true) {
		const pid_t done = waitpid(p_pid, &r_status, WNOHANG);
		if (done == p_pid || (done < 0 && errno == ECHILD)) {
			return true;
		}
		if (monotonic_now_ns() > give_up) {
			return false;
		}
		sleep_for_ns(20'000'000);
	}
}

// SIGTERM, a grace period, then SIGKILL; always reaps.
void terminate(pid_t p_pid) {
	if (p_pid <= 0) {
		return;
	}
	int status = 0;
	kill(p_pid, SIGTERM);
	if (!wait_for_exit(p_pid, GRACE_S, status)) {
		kill(p_pid, SIGKILL);
		waitpid(p_pid, &status, 0);
	}
}

} // namespace

bool run_and_capture(const std::vector<std::string> &p_argv, double p_timeout_s, std::string &r_output,
		std::string &r_error) {
	int out[2];
	if (pipe2(out, O_CLOEXEC) != 0) {
		r_error = std::strerror(errno);
		return false;
	}
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
	posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
	pid_t pid = -1;
	std::vector<char *> argv = c_argv(p_argv);
	const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
	posix_spawn_file_actions_destroy(&actions);
	close(out[1]);
	if (spawned != 0) {
		close(out[0]);
		r_error = p_argv[0] + " not found or not runnable (" + std::strerror(spawned) + "; make deps installs rt-tests)";
		return false;
	}
	const int64_t give_up = monotonic_now_ns() + static_cast<int64_t>(p_timeout_s * 1e9);
	char buffer[65536];
	bool timed_out = false;
	while (true) {
		pollfd readable{ out[0], POLLIN, 0 };
		const int ready = poll(&readable, 1, 200);
		if (ready > 0) {
			const ssize_t got = read(out[0], buffer, sizeof(buffer));
			if (got <= 0) {
				break;
			}
			r_output.append(buffer, static_cast<size_t>(got));
		}
		if (monotonic_now_ns() > give_up) {
			timed_out = true;
			break;
		}
	}
	close(out[0]);
	if (timed_out) {
		terminate(pid);
		r_error = p_argv[0] + " did not finish in time";
		return false;
	}
	int status = 0;
	waitpid(pid, &status, 0);
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		r_error = p_argv[0] + " failed (status " + std::to_string(status) + ")";
		return false;
	}
	return true;
}

RenderLoad::RenderLoad(std::string p_project) :
		project_(std::move(p_project)), log_path_(project_ + "/.bench/render-load-game.log") {}

RenderLoad::~RenderLoad() {
	stop();
}

bool RenderLoad::start(std::string &r_why_not) {
	int display_pipe[2];
	if (pipe2(display_pipe, O_CLOEXEC) != 0) {
		r_why_not = std::strerror(errno);
		return false;
	}
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_adddup2(&actions, display_pipe[1], 3); // -displayfd 3
	posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
	posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
	std::vector<std::string> xvfb = { "Xvfb", "-displayfd", "3", "-screen", "0", "1280x720x24", "-nolisten", "tcp" };
	std::vector<char *> argv = c_argv(xvfb);
	const int spawned = posix_spawnp(&xvfb_pid_, "Xvfb", &actions, nullptr, argv.data(), environ);
	posix_spawn_file_actions_destroy(&actions);
	close(display_pipe[1]);
	if (spawned != 0) {
		close(display_pipe[0]);
		xvfb_pid_ = -1;
		r_why_not = std::string("Xvfb is not available here (") + std::strerror(spawned) + "; make deps installs xvfb)";
		return false;
	}
	char number[32] = {};
	size_t got = 0;
	pollfd readable{ display_pipe[0], POLLIN, 0 };
	while (got == 0 || number[got - 1] != '\n') {
		if (poll(&readable, 1, 10000) <= 0) {
			break;
		}
		const ssize_t n = read(display_pipe[0], number + got, sizeof(number) - 1 - got);
		if (n <= 0) {
			break;
		}
		got += static_cast<size_t>(n);
	}
	close(display_pipe[0]);
	if (got == 0) {
		r_why_not = "Xvfb did not report a display";
		stop();
		return false;
	}
	display_ = ":" + std::string(number, std::strcspn(number, "\n"));
	if (!spawn_game(r_why_not)) {
		stop();
		return false;
	}
	// Playing once the autopilot prints its first status line.
	const int64_t give_up = monotonic_now_ns() + 90'000'000'000LL;
	while (monotonic_now_ns() < give_up) {
		std::ifstream log(log_path_);
		std::stringstream text;
		text << log.rdbuf();
		if (text.str().find("\nt= 1.0s") != std::string::npos) {
			watcher_ = std::thread([this] { watch(); });
			return true;
		}
		int status = 0;
		if (waitpid(game_pid_.load(), &status, WNOHANG) == game_pid_.load()) {
			game_pid_.store(-1);
			r_why_not = "the game exited before playing (log: " + log_path_ + ")";
			stop();
			return false;
		}
		sleep_for_ns(100'000'000);
	}
	r_why_not = "the game did not start playing within 90 s (log: " + log_path_ + ")";
	stop();
	return false;
}

bool RenderLoad::spawn_game(std::string &r_why_not) {
	const std::string godot = project_ + "/tools/godot";
	std::vector<std::string> args;
	if (::geteuid() == 0) {
		// The load is rendering, not a second real-time servo: as root the game's own servo
		// would take SCHED_FIFO 80 and hold /dev/cpu_dma_latency for everyone measured beside
		// it. In a mount namespace of its own the latency file is /dev/null, and without
		// CAP_SYS_NICE SCHED_FIFO is refused (and there is no RealtimeKit to ask on NO_SYSTEM_BUS).
		args = { "unshare", "--mount", "--", "sh", "-c", "mount --bind /dev/null /dev/cpu_dma_latency && exec \"$@\"", "sh",
			"setpriv", "--bounding-set=-sys_nice", "--inh-caps=-sys_nice", "--" };
	}
	// Level 1 under the test driver's autopilot (the product has no autopilot of its own).
	args.insert(args.end(), { godot, "--path", project_, "--rendering-driver", "opengl3", "--audio-driver", "Dummy", "res://tests/drivers/game_autopilot.tscn", "--", "--autopilot-seconds=0" });
	std::vector<std::string> environment;
	for (char **entry = environ; *entry; ++entry) {
		if (std::strncmp(*entry, "DISPLAY=", 8) != 0 && std::strncmp(*entry, "DBUS_SYSTEM_BUS_ADDRESS=", 24) != 0) {
			environment.emplace_back(*entry);
		}
	}
	environment.push_back("DISPLAY=" + display_);
	environment.push_back(std::string("DBUS_SYSTEM_BUS_ADDRESS=") + NO_SYSTEM_BUS);
	std::vector<char *> envp = c_argv(environment);
	std::vector<char *> argv = c_argv(args);
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
	pid_t pid = -1;
	const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
	posix_spawn_file_actions_destroy(&actions);
	if (spawned != 0) {
		r_why_not = args[0] + " cannot be run (" + std::strerror(spawned) + ")";
		return false;
	}
	game_pid_.store(pid);
	return true;
}

// The autopilot quits at the goal: start the game again so the load lasts.
void RenderLoad::watch() {
	while (!stopping_.load()) {
		const pid_t pid = game_pid_.load();
		int status = 0;
		if (pid > 0 && waitpid(pid, &status, WNOHANG) == pid) {
			game_pid_.store(-1);
			std::string ignored;
			if (!stopping_.load() && spawn_game(ignored)) {
				restarts_.fetch_add(1);
			}
		}
		sleep_for_ns(100'000'000);
	}
}

void RenderLoad::stop() {
	stopping_.store(true);
	if (watcher_.joinable()) {
		watcher_.join();
	}
	terminate(game_pid_.exchange(-1));
	terminate(xvfb_pid_);
	xvfb_pid_ = -1;
}

std::string RenderLoad::describe() const {
	return "the game windowed under Xvfb " + display_ +
			" (Compatibility renderer, llvmpipe), level 1 under its autopilot, its own servo without real-time rights; "
			"restarted at the goal " +
			std::to_string(restarts_.load()) + " time(s)";
}

} // namespace haptics::bench
