// ScratchDir (scratch_dir.h): the folder exists while the test holds it and is gone after,
// with everything inside, also when the test fails.

#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

using namespace haptics;
namespace fs = std::filesystem;

namespace {

void fill(const testing::ScratchDir &p_dir) {
	fs::create_directories(p_dir / "study/P01/telemetry");
	std::ofstream(p_dir / "study/P01/telemetry/x.csv") << "t\n1\n";
	std::ofstream(p_dir / "top.txt") << "x";
#ifndef _WIN32 // Windows makes links only with a privilege (or developer mode)
	fs::create_symlink(p_dir / "study", p_dir / "link");
#endif
}

} // namespace

TEST_CASE("scratch_dir: a fresh folder under the temporary directory, removed with its contents") {
	fs::path root;
	{
		const testing::ScratchDir dir("haptics-scratch");
		root = dir.root();
		CHECK(fs::is_directory(root));
		// Not fs::equivalent: under Wine, MinGW's libstdc++ calls a folder and itself different.
		CHECK(fs::canonical(fs::temp_directory_path() / root.filename()) == fs::canonical(root));
		CHECK(root.filename().string().rfind("haptics-scratch-", 0) == 0);
		CHECK(fs::is_empty(root));
		fill(dir);
		const testing::ScratchDir other("haptics-scratch");
		CHECK(other.root() != root);
	}
	CHECK_FALSE(fs::exists(root));
}

// Run only by CTest's scratch_failing_test_cleans_up (cmake/check_scratch.cmake), which
// expects this case to fail and its folders to be gone afterwards.
TEST_CASE("scratch_dir: a failing test still removes its folders" * doctest::skip()) {
	const testing::ScratchDir outer("haptics-scratch-failing");
	fill(outer);
	CHECK_MESSAGE(false, "fails on purpose (a CHECK: the test goes on)");
	const testing::ScratchDir inner("haptics-scratch-failing");
	fill(inner);
	REQUIRE_MESSAGE(false, "fails on purpose (a REQUIRE: unwinds through both folders)");
}
