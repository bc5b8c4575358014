#pragma once

// The one way a doctest gets a folder of its own: a fresh directory in the system's temporary
// directory (std::filesystem::temp_directory_path(), so $TMPDIR when set), removed with
// everything in it when the object goes out of scope, also when the test fails (a failed
// REQUIRE unwinds through the destructor). CTest runs the suite with TMPDIR pointing into the
// build tree and checks afterwards that nothing was left there (CMakeLists.txt,
// cmake/check_scratch.cmake).

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace haptics::testing {

class ScratchDir {
public:
	// p_prefix names the folder, e.g. "haptics-durable" gives haptics-durable-XXXXXX.
	explicit ScratchDir(const char *p_prefix) {
		std::string pattern = (std::filesystem::temp_directory_path() / (std::string(p_prefix) + "-XXXXXX")).string();
		REQUIRE_MESSAGE(::mkdtemp(pattern.data()) != nullptr, "mkdtemp failed for ", pattern);
		root_ = pattern;
	}
	~ScratchDir() {
		std::error_code ignored;
		std::filesystem::remove_all(root_, ignored);
	}
	ScratchDir(const ScratchDir &) = delete;
	ScratchDir &operator=(const ScratchDir &) = delete;

	const std::filesystem::path &root() const { return root_; }
	// p_name inside the folder, e.g. "ratings.csv" or "study/P01".
	std::filesystem::path operator/(const std::string &p_name) const { return root_ / p_name; }

private:
	std::filesystem::path root_;
};

} // namespace haptics::testing
