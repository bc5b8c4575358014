#include "rt_jobs.h"

#include "core/base/realtime.h"

#include <cstdlib>
#include <cstring>

namespace haptics::bench {

namespace {

// The old servo: SCHED_FIFO 50 and none of the other techniques.
ServoOptions baseline_options() {
	ServoOptions options;
	options.realtime.priority = 50;
	options.realtime.lock_memory = false;
	options.realtime.hold_cpu_latency = false;
	options.realtime.cpu = PIN_NONE;
	options.realtime.prefault_stack_kb = 0;
	options.realtime.minimise_timer_slack = false;
	options.spin_ns = 0;
	return options;
}

void add_techniques(std::vector<Job> &r_jobs) {
	const ServoOptions base = baseline_options();
	const auto add = [&](const std::string &p_label, const ServoOptions &p_options) {
		r_jobs.push_back({ p_label, JobKind::SERVO, p_options, false, false });
	};
	add("before: SCHED_FIFO 50 only", base);
	ServoOptions o = base;
	o.realtime.lock_memory = true;
	add("+ mlockall", o);
	o = base;
	o.realtime.hold_cpu_latency = true;
	add("+ cpu_dma_latency 0", o);
	o = base;
	o.realtime.priority = 80;
	add("+ SCHED_FIFO 80", o);
	o = base;
	o.realtime.cpu = PIN_AUTO;
	add("+ pinned (last CPU)", o);
	o = base;
	o.realtime.prefault_stack_kb = 256;
	add("+ stack prefault 256 KiB", o);
	o = base;
	o.realtime.priority = 0;
	add("SCHED_OTHER, default timer slack", o);
	o.realtime.minimise_timer_slack = true;
	add("SCHED_OTHER + timer slack 1 ns", o);
	for (int64_t spin_us : { 0, 10, 25, 50, 100 }) {
		ServoOptions spun;
		spun.spin_ns = spin_us * 1000;
		add("defaults, spin " + std::to_string(spin_us) + " us", spun);
	}
	add("defaults (as shipped)", ServoOptions());
}

// Root configured as RealtimeKit configures a user: the same priority, no latency hold.
void add_root_as_user(std::vector<Job> &r_jobs, bool p_more) {
	ServoOptions o;
	o.realtime.priority = RTKIT_DEFAULT_MAX_PRIORITY;
	o.realtime.hold_cpu_latency = false;
	const std::string priority = std::to_string(RTKIT_DEFAULT_MAX_PRIORITY);
	r_jobs.push_back({ "root, FIFO " + priority + ", no cpu_dma_latency", JobKind::SERVO, o, false, false });
	if (!p_more) {
		return;
	}
	o.realtime.hold_cpu_latency = true;
	r_jobs.push_back({ "root, FIFO " + priority + " + cpu_dma_latency", JobKind::SERVO, o, false, false });
	o = ServoOptions();
	o.realtime.hold_cpu_latency = false;
	r_jobs.push_back({ "root, FIFO " + std::to_string(o.realtime.priority) + ", no cpu_dma_latency", JobKind::SERVO, o,
			false, false });
}

void add_user(std::vector<Job> &r_jobs, const JobPlan &p_plan) {
	const std::string as = "as " + p_plan.user;
	const auto add = [&](const std::string &p_label, const ServoOptions &p_options, bool p_rtkit,
							 bool p_latency_access = false) {
		r_jobs.push_back({ as + ", " + p_label, JobKind::USER_SERVO, p_options, p_rtkit, p_latency_access });
	};
	add("no RealtimeKit", ServoOptions(), false);
	if (p_plan.user_techniques) {
		ServoOptions o;
		o.realtime.minimise_timer_slack = false;
		add("no RealtimeKit, default timer slack", o, false);
		o = ServoOptions();
		o.spin_ns = ServoOptions::DEFAULT_SPIN_NS; // What a real-time servo spins.
		add("no RealtimeKit, spin " + std::to_string(o.spin_ns / 1000) + " us", o, false);
	}
	if (!p_plan.rtkit) {
		return;
	}
	add("RealtimeKit, spin learned", ServoOptions(), true);
	ServoOptions fixed;
	fixed.spin_ns = ServoOptions::UNHELD_SPIN_NS; // The fixed spin the learned one replaced.
	add("RealtimeKit, spin " + std::to_string(fixed.spin_ns / 1000) + " us fixed", fixed, true);
	add("RealtimeKit + cpu_dma_latency", ServoOptions(), true, true); // As the udev rule gives it.
	if (!p_plan.user_techniques) {
		return;
	}
	for (int64_t spin_us : { 0, 200 }) {
		ServoOptions o;
		o.spin_ns = spin_us * 1000;
		add("RealtimeKit, spin " + std::to_string(spin_us) + " us", o, true);
	}
	ServoOptions o;
	o.realtime.cpu = PIN_AUTO;
	add("RealtimeKit, pinned (last CPU)", o, true);
}

} // namespace

std::vector<Job> plan_jobs(const JobPlan &p_plan) {
	std::vector<Job> jobs = { { "servo", JobKind::SERVO, ServoOptions(), false, false },
		{ "cyclictest", JobKind::CYCLICTEST, ServoOptions(), false, false } };
	if (p_plan.techniques) {
		add_techniques(jobs);
	}
	if (!p_plan.user.empty()) {
		add_root_as_user(jobs, p_plan.user_techniques);
		add_user(jobs, p_plan);
	}
	return jobs;
}

std::vector<std::string> user_child_arguments(const ServoOptions &p_options) {
	return { "--spin-ns", std::to_string(p_options.spin_ns), "--pin", std::to_string(p_options.realtime.cpu),
		"--timer-slack", p_options.realtime.minimise_timer_slack ? "1" : "0" };
}

bool parse_user_child_argument(int p_argc, char **p_argv, int &r_index, ServoOptions &r_options) {
	if (r_index + 1 >= p_argc) {
		return false;
	}
	const char *name = p_argv[r_index];
	const char *value = p_argv[r_index + 1];
	if (std::strcmp(name, "--spin-ns") == 0) {
		r_options.spin_ns = std::atoll(value);
	} else if (std::strcmp(name, "--pin") == 0) {
		r_options.realtime.cpu = std::atoi(value);
	} else if (std::strcmp(name, "--timer-slack") == 0) {
		r_options.realtime.minimise_timer_slack = std::strcmp(value, "0") != 0;
	} else {
		return false;
	}
	++r_index;
	return true;
}

} // namespace haptics::bench
