#pragma once

// Sets (or, for nullptr, unsets) an environment variable for one scope, restoring the
// previous value after; on Windows through the C runtime's _putenv_s, whose empty value
// unsets (getenv sees the change there as setenv's is seen here).

#include <cstdlib>
#include <string>

namespace haptics::testing {

inline void set_environment_variable(const char *p_name, const char *p_value) {
#ifdef _WIN32
	_putenv_s(p_name, p_value != nullptr ? p_value : "");
#else
	if (p_value != nullptr) {
		setenv(p_name, p_value, 1);
	} else {
		unsetenv(p_name);
	}
#endif
}

class ScopedVariable {
public:
	ScopedVariable(const char *p_name, const char *p_value) :
			name_(p_name) {
		if (const char *old = std::getenv(p_name)) {
			previous_ = old;
			had_ = true;
		}
		set_environment_variable(p_name, p_value);
	}
	~ScopedVariable() { set_environment_variable(name_.c_str(), had_ ? previous_.c_str() : nullptr); }
	ScopedVariable(const ScopedVariable &) = delete;
	ScopedVariable &operator=(const ScopedVariable &) = delete;

private:
	std::string name_;
	std::string previous_;
	bool had_ = false;
};

} // namespace haptics::testing
