#pragma once

// What the VM's test program prints on the serial console, one line each, for
// tools/kernel/run.sh to read:
//   KTEST <scenario> PASS|FAIL <what>          a check
//   KWIRE <scenario> <what>: <hex bytes>       bytes the device model received
//   KINFO <scenario> <what>                    a measurement or a fact worth the log
// A scenario is a function; a failed check does not stop it (the next may say why).

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <thread>

namespace haptics::vm {

class Report {
public:
	explicit Report(std::string p_scenario) :
			scenario_(std::move(p_scenario)) {}

	// Prints the check and counts it; returns p_ok.
	bool check(bool p_ok, const std::string &p_what);
	void wire(const std::string &p_what, std::span<const uint8_t> p_bytes);
	void info(const std::string &p_what);

	int failed() const { return failed_; }
	int passed() const { return passed_; }

private:
	std::string scenario_;
	int passed_ = 0;
	int failed_ = 0;
};

// Polls p_condition every 5 ms for up to p_seconds; true as soon as it holds.
template <typename Condition>
bool eventually(Condition p_condition, double p_seconds) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (std::chrono::steady_clock::now() < deadline) {
		if (p_condition()) {
			return true;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
	}
	return p_condition();
}

std::string hex(std::span<const uint8_t> p_bytes);

} // namespace haptics::vm
