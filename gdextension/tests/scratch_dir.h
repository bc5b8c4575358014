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
#include <random>
#include <string>
#include <system_error>

namespace haptics::testing {

class ScratchDir {
public:
	// p_prefix names the folder, e.g. "haptics-durable" gives haptics-durable-XXXXXX.
	// The suffix is random and the folder made only if new (mkdtemp's rule; Windows has no
	// mkdtemp).
	explicit ScratchDir(const char *p_prefix) {
		constexpr char LETTERS[] = "abcdefghijklmnopqrstuvwxyz0123456789";
		std::random_device entropy;
		std::uniform_int_distribution<size_t> pick(0, sizeof(LETTERS) - 2);
		std::error_code error;
		for (int attempt = 0; attempt < 100 && root_.empty(); ++attempt) {
			std::string name = std::string(p_prefix) + "-";
			for (int i = 0; i < 6; ++i) {
				name += LETTERS[pick(entropy)];
			}
			const std::filesystem::path candidate = std::filesystem::temp_directory_path() / name;
			if (std::filesystem::create_directory(candidate, error)) {
				root_ = candidate;
			}
		}
		REQUIRE_MESSAGE(!root_.empty(), "cannot make a scratch folder for ", p_prefix, ": ", error.message());
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
