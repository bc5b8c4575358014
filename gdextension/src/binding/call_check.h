// Argument-count rules for Variant calls, kept free of engine types so doctest can check
// them without an engine.
#pragma once

#include <cstdint>

namespace gd {

struct CallCheck {
	enum Error { OK,
		TOO_MANY,
		TOO_FEW };
	Error error = OK;
	// For TOO_MANY the maximum, for TOO_FEW the minimum argument count (what the engine
	// prints as "expected N").
	int64_t expected = 0;
};

// p_params parameters, the last p_defaults of which have default values.
constexpr CallCheck check_argument_count(int64_t p_params, int64_t p_defaults, int64_t p_given) {
	const int64_t required = p_params - p_defaults;
	if (p_given > p_params) {
		return { CallCheck::TOO_MANY, p_params };
	}
	if (p_given < required) {
		return { CallCheck::TOO_FEW, required };
	}
	return { CallCheck::OK, 0 };
}

} // namespace gd
