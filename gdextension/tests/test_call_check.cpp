// The binding's engine-free argument-count rules: what the engine is told when GDScript
// calls a method with too many or too few arguments.
#include <doctest/doctest.h>

#include "binding/call_check.h"

using gd::CallCheck;
using gd::check_argument_count;

TEST_CASE("call_check: exact argument counts pass") {
	CHECK(check_argument_count(0, 0, 0).error == CallCheck::OK);
	CHECK(check_argument_count(3, 0, 3).error == CallCheck::OK);
}

TEST_CASE("call_check: too many arguments report the maximum") {
	const CallCheck check = check_argument_count(1, 0, 2);
	CHECK(check.error == CallCheck::TOO_MANY);
	CHECK(check.expected == 1);
	CHECK(check_argument_count(0, 0, 1).expected == 0);
}

TEST_CASE("call_check: too few arguments report the minimum") {
	const CallCheck check = check_argument_count(3, 0, 1);
	CHECK(check.error == CallCheck::TOO_FEW);
	CHECK(check.expected == 3);
}

TEST_CASE("call_check: defaults lower the minimum but not the maximum") {
	// start(rate_hz = 1000): zero or one argument.
	CHECK(check_argument_count(1, 1, 0).error == CallCheck::OK);
	CHECK(check_argument_count(1, 1, 1).error == CallCheck::OK);
	CHECK(check_argument_count(1, 1, 2).error == CallCheck::TOO_MANY);
	// f(a, b = 1, c = 2): one to three.
	const CallCheck none = check_argument_count(3, 2, 0);
	CHECK(none.error == CallCheck::TOO_FEW);
	CHECK(none.expected == 1);
	CHECK(check_argument_count(3, 2, 2).error == CallCheck::OK);
}

static_assert(check_argument_count(2, 1, 1).error == CallCheck::OK, "usable at compile time");
