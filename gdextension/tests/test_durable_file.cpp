// Durable writes on a real file system: bytes on disk, never overwritten, folders created.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scratch_dir.h"
#include "storage/durable_file.h"

using namespace haptics;

namespace {

// Each test's folder (scratch_dir.h); p_name inside it, e.g. "/ratings.csv".
class TempDir {
public:
	std::string path(const char *p_name) const { return scratch_.root().string() + p_name; }

private:
	testing::ScratchDir scratch_{ "haptics-durable" };
};

std::string read_file(const std::string &p_path) {
	std::ifstream in(p_path, std::ios::binary);
	std::stringstream contents;
	contents << in.rdbuf();
	return contents.str();
}

} // namespace

TEST_CASE("durable_append: creates, then appends without touching earlier bytes") {
	const TempDir dir;
	const std::string path = dir.path("/ratings.csv");
	REQUIRE(durable_append(path, "header\n").ok());
	REQUIRE(durable_append(path, "a,1\n").ok());
	REQUIRE(durable_append(path, "b,2\n").ok());
	CHECK(read_file(path) == "header\na,1\nb,2\n");
	bool complete = false;
	REQUIRE(check_complete_lines(path, complete).ok());
	CHECK(complete);
}

TEST_CASE("check_complete_lines: a record cut short is detected") {
	const TempDir dir;
	const std::string path = dir.path("/trials.csv");
	REQUIRE(durable_append(path, "header\nrow,1\nrow,").ok());
	bool complete = true;
	REQUIRE(check_complete_lines(path, complete).ok());
	CHECK_FALSE(complete);
	CHECK_FALSE(check_complete_lines(dir.path("/missing.csv"), complete).ok());
}

TEST_CASE("durable_write: never overwrites unless asked, and replaces atomically") {
	const TempDir dir;
	const std::string path = dir.path("/participant.json");
	REQUIRE(durable_write(path, "{\"v\":1}", false).ok());
	const Status refused = durable_write(path, "{\"v\":2}", false);
	CHECK_FALSE(refused.ok());
	CHECK(std::string(refused.message()).find("never overwritten") != std::string::npos);
	CHECK(read_file(path) == "{\"v\":1}");
	REQUIRE(durable_write(path, "{\"v\":3}", true).ok());
	CHECK(read_file(path) == "{\"v\":3}");
	CHECK_FALSE(std::filesystem::exists(path + ".tmp")); // no temporary left behind
}

TEST_CASE("make_directories: nested folders, existing ones fine, errors named") {
	const TempDir dir;
	REQUIRE(make_directories(dir.path("/study/P01/telemetry")).ok());
	REQUIRE(make_directories(dir.path("/study/P01/telemetry")).ok());
	REQUIRE(durable_append(dir.path("/study/P01/telemetry/x.csv"), "t\n").ok());
	REQUIRE(durable_append(dir.path("/file"), "x").ok());
	const Status blocked = make_directories(dir.path("/file/sub"));
	CHECK_FALSE(blocked.ok());
	CHECK(std::string(blocked.message()).find("file/sub") != std::string::npos);
}

TEST_CASE("durable_append: an unwritable place is a clear error") {
	// A folder that is a file: refused on every platform, whoever runs the test.
	const TempDir dir;
	REQUIRE(durable_append(dir.path("/plain"), "x").ok());
	const std::string path = dir.path("/plain/ratings.csv");
	const Status status = durable_append(path, "x");
	CHECK_FALSE(status.ok());
	CHECK(std::string(status.message()).find(path) != std::string::npos);
	CHECK_FALSE(durable_write(path, "x", true).ok());
}
