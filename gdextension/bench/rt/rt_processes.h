#pragma once

// The processes haptics_rt_bench starts: cyclictest, run to completion with its output
// captured, and the rendering load (Xvfb and the game under its autopilot, restarted if it
// reaches the goal). Every one is stopped by its PID (SIGTERM, then SIGKILL after a grace
// period), never by name.

#include <sys/types.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

namespace haptics::bench {

// A bus nobody listens on: RealtimeKit is then "unavailable" to whoever is given it, as on a
// machine without a system bus.
inline constexpr const char *NO_SYSTEM_BUS = "unix:path=/nonexistent/haptics-no-bus";

// Runs p_argv (searched on PATH) to completion, stdout into r_output; false with the reason in
// r_error if it cannot start, exceeds p_timeout_s (then it is killed) or exits non-zero.
bool run_and_capture(const std::vector<std::string> &p_argv, double p_timeout_s, std::string &r_output,
		std::string &r_error);

class RenderLoad {
public:
	explicit RenderLoad(std::string p_project);
	~RenderLoad(); // stop()
	RenderLoad(const RenderLoad &) = delete;
	RenderLoad &operator=(const RenderLoad &) = delete;

	// Starts Xvfb and the game windowed on it, and waits until the game plays (its
	// autopilot's first status line). False with the reason when that cannot be done here.
	bool start(std::string &r_why_not);
	void stop();
	std::string describe() const;

private:
	bool spawn_game(std::string &r_why_not);
	void watch();

	std::string project_;
	std::string log_path_;
	std::string display_;
	pid_t xvfb_pid_ = -1;
	std::atomic<pid_t> game_pid_{ -1 };
	std::atomic<bool> stopping_{ false };
	std::atomic<int> restarts_{ 0 };
	std::thread watcher_;
};

} // namespace haptics::bench
