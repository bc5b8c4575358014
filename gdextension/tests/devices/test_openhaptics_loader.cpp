// The OpenHaptics runtime loader and the backend's entry points: a missing library, a
// broken one, a missing function, the search order, probe/open_device, and hdGetError's
// struct returned by value (docs/devices/openhaptics.md), all through the system's real loader (dlopen,
// LoadLibrary under Wine: dynamic_library.h).

#include "devices/dynamic_library.h"
#include "devices/openhaptics/hd_api.h"
#include "devices/openhaptics/hd_runtime.h"
#include "devices/openhaptics/openhaptics_backend.h"
#include "openhaptics_fake.h"

#include "scoped_variable.h"
#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace haptics;
using namespace haptics::openhaptics;
using haptics::test::fresh_fake_hd;

namespace {

constexpr char MISSING_LIBRARY[] = "/nonexistent/haptics-test/libHD.so";

bool contains(const char *p_text, const char *p_part) {
	return std::strstr(p_text, p_part) != nullptr;
}

// HAPTICS_OPENHAPTICS_LIBRARY for one scope (nullptr: unset).
class ScopedLibraryVariable : public testing::ScopedVariable {
public:
	explicit ScopedLibraryVariable(const char *p_value) :
			ScopedVariable(HD_LIBRARY_ENV, p_value) {}
};

} // namespace

TEST_CASE("openhaptics: a missing runtime library is a clean NO_DEVICE, never a crash") {
	HdLibrary library;
	const Status status = library.load(MISSING_LIBRARY);
	CHECK(status.code() == StatusCode::NO_DEVICE);
	CHECK(contains(status.message(), MISSING_LIBRARY));
#ifndef _WIN32
	CHECK(contains(status.message(), "cannot open shared object file")); // glibc's words
#endif
	CHECK_FALSE(library.is_loaded());
	CHECK((library.api().hdInitDevice == nullptr));

	HdLibrary searched;
	const Status through_search = load_hd_runtime(MISSING_LIBRARY, searched);
	CHECK(through_search.code() == StatusCode::NO_DEVICE);
	CHECK(std::strncmp(through_search.message(), HD_RUNTIME_NOT_FOUND, std::strlen(HD_RUNTIME_NOT_FOUND)) == 0);

	// The device stays closed and its servo side says so.
	auto device = make_device_on_runtime(MISSING_LIBRARY);
	const Status opened = device->open();
	CHECK(opened.code() == StatusCode::NO_DEVICE);
	CHECK_FALSE(device->is_open());
	DeviceState state;
	CHECK(device->read_state(state) == DeviceIo::FAILED);
	CHECK(device->write_zero() == DeviceIo::FAILED);
	device->close(); // Harmless.
}

TEST_CASE("openhaptics: a file that is there but not a library is reported as broken, not missing") {
	const testing::ScratchDir dir("haptics-openhaptics");
	const std::filesystem::path path = dir / "not-a-library.so";
	{
		std::ofstream file(path);
		file << "not an ELF file\n";
	}
	HdLibrary library;
	const std::string path_text = path.string();
	const Status status = library.load(path_text.c_str());
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(contains(status.message(), path_text.c_str()));
	CHECK_FALSE(library.is_loaded());
}

TEST_CASE("openhaptics: a runtime without hdScheduleAsynchronous is refused, naming the function") {
	HdLibrary library;
	const Status status = library.load(HAPTICS_FAKE_HD_NO_ASYNC_PATH);
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(contains(status.message(), "hdScheduleAsynchronous"));
	CHECK_FALSE(library.is_loaded());

	// Through the device: the same Status, and not one HD function was called.
	auto device = make_device_on_runtime(HAPTICS_FAKE_HD_NO_ASYNC_PATH);
	const Status opened = device->open();
	CHECK(opened.code() == StatusCode::DEVICE_ERROR);
	CHECK(contains(opened.message(), "lacks the function hdScheduleAsynchronous"));
	CHECK_FALSE(device->is_open());
	char error[256];
	bool missing = false;
	void *handle = open_dynamic_library(HAPTICS_FAKE_HD_NO_ASYNC_PATH, missing, error, sizeof(error));
	REQUIRE(handle != nullptr);
	size_t (*call_count)() = nullptr;
	haptics::test::fake_hd_resolve(handle, "fake_hd_call_count", call_count);
	CHECK(call_count() == 0);
	close_dynamic_library(handle);
}

TEST_CASE("openhaptics: every function we use resolves in the fake, and unload forgets them") {
	HdLibrary library;
	REQUIRE(library.load(HAPTICS_FAKE_HD_PATH));
	CHECK(library.is_loaded());
	CHECK(std::strcmp(library.path(), HAPTICS_FAKE_HD_PATH) == 0);
	CHECK((library.api().hdGetError != nullptr));
	CHECK((library.api().hdGetErrorString != nullptr));
	CHECK((library.api().hdScheduleAsynchronous != nullptr));
	library.unload();
	CHECK_FALSE(library.is_loaded());
	CHECK((library.api().hdGetError == nullptr));
	CHECK(library.path()[0] == '\0');
}

TEST_CASE("openhaptics: hdGetError's 12-byte struct comes back by value, field by field") {
	auto &fake = fresh_fake_hd();
	HdLibrary library;
	REQUIRE(library.load(HAPTICS_FAKE_HD_PATH));
	fake.push_error(0x0201, 123, 0);
	fake.push_error(0x0302, -5, 7);
	const HDErrorInfo newest = library.api().hdGetError();
	CHECK(newest.errorCode == HD_COMM_ERROR);
	CHECK(newest.internalErrorCode == -5);
	CHECK(newest.hHD == 7u);
	const HDErrorInfo older = library.api().hdGetError();
	CHECK(older.errorCode == HD_EXCEEDED_MAX_FORCE);
	CHECK(older.internalErrorCode == 123);
	CHECK(older.hHD == 0u);
	const HDErrorInfo empty = library.api().hdGetError();
	CHECK(empty.errorCode == HD_SUCCESS);
	CHECK(empty.internalErrorCode == 0);

	char text[200];
	format_hd_error(&library.api(), older, text, sizeof(text));
	CHECK(std::string(text) ==
			"HD error 0x0201 (HD_EXCEEDED_MAX_FORCE): fake: the force exceeded the device's maximum, internal error 123");
	HdApi without_strings = library.api();
	without_strings.hdGetErrorString = nullptr;
	format_hd_error(&without_strings, older, text, sizeof(text));
	CHECK(std::string(text) == "HD error 0x0201 (HD_EXCEEDED_MAX_FORCE), internal error 123");
	format_hd_error(nullptr, HDErrorInfo{ 0x0999, 1, 0 }, text, sizeof(text));
	CHECK(std::string(text) == "HD error 0x0999 (unknown HD error), internal error 1");
	CHECK(std::string(hd_error_name(HD_COMM_ERROR)) == "HD_COMM_ERROR");
	CHECK(std::string(hd_error_name(HD_INVALID_LICENSE)) == "HD_INVALID_LICENSE");
}

TEST_CASE("openhaptics: the search tries HAPTICS_OPENHAPTICS_LIBRARY first, then the sonames") {
	{
		ScopedLibraryVariable variable(HAPTICS_FAKE_HD_PATH);
		const HdRuntimeLocation location = runtime_location();
		CHECK(location.loadable);
		CHECK(location.path == HAPTICS_FAKE_HD_PATH);
		CHECK(location.reason.empty());
		const DeviceInfo info = make_default_device_info();
		CHECK(info.id == OPENHAPTICS_DEFAULT_DEVICE_ID);
		CHECK(info.backend == BACKEND_OPENHAPTICS);
		CHECK(info.driver == DRIVER_OPENHAPTICS);
		CHECK(info.path == HAPTICS_FAKE_HD_PATH);
		CHECK(info.openable);
	}
	// This machine has no OpenHaptics: with the variable unset nothing loads, and the reason
	// is the sentence the player sees.
	{
		ScopedLibraryVariable variable(nullptr);
		const HdRuntimeLocation location = runtime_location();
		CHECK_FALSE(location.loadable);
		CHECK(location.reason == HD_RUNTIME_NOT_FOUND);
		const DeviceInfo info = make_default_device_info();
		CHECK_FALSE(info.openable);
		CHECK(info.unavailable_reason == HD_RUNTIME_NOT_FOUND);
	}
	{
		ScopedLibraryVariable variable(MISSING_LIBRARY);
		const HdRuntimeLocation location = runtime_location();
		CHECK_FALSE(location.loadable);
		CHECK(contains(location.reason.c_str(), HD_RUNTIME_NOT_FOUND));
		CHECK(contains(location.reason.c_str(), MISSING_LIBRARY));
	}
	{
		ScopedLibraryVariable variable(HAPTICS_FAKE_HD_NO_ASYNC_PATH);
		const HdRuntimeLocation location = runtime_location();
		CHECK_FALSE(location.loadable);
		CHECK(contains(location.reason.c_str(), "hdScheduleAsynchronous"));
	}
}

TEST_CASE("openhaptics: probe handles only its backend and says why it cannot open") {
	DeviceInfo other;
	other.backend = "hidapi";
	CHECK_FALSE(probe(other).handled);

	DeviceInfo info;
	info.id = OPENHAPTICS_DEFAULT_DEVICE_ID;
	info.backend = BACKEND_OPENHAPTICS;
	info.path = HAPTICS_FAKE_HD_PATH;
	const DeviceAvailability available = probe(info);
	CHECK(available.handled);
	CHECK(available.openable);
	CHECK(available.reason.empty());

	info.path = MISSING_LIBRARY;
	const DeviceAvailability missing = probe(info);
	CHECK(missing.handled);
	CHECK_FALSE(missing.openable);
	CHECK(missing.reason.rfind(HD_RUNTIME_NOT_FOUND, 0) == 0);
}

TEST_CASE("openhaptics: open_device opens the device over the runtime named in the DeviceInfo") {
	auto &fake = fresh_fake_hd();
	DeviceInfo info;
	info.id = OPENHAPTICS_DEFAULT_DEVICE_ID;
	info.backend = BACKEND_OPENHAPTICS;
	info.path = HAPTICS_FAKE_HD_PATH;
	std::unique_ptr<HapticDevice> device;
	REQUIRE(open_device(info, device));
	REQUIRE(device != nullptr);
	CHECK(device->is_open());
	CHECK(std::string(device->name()) == "Touch");
	CHECK(fake.scheduler_running());
	CHECK(device->open()); // Idempotent: the engine opens it again.
	device->close();
	CHECK_FALSE(fake.scheduler_running());

	info.backend = "libusb";
	std::unique_ptr<HapticDevice> none;
	CHECK(open_device(info, none).code() == StatusCode::INVALID_ARGUMENT);
	CHECK(none == nullptr);
	info.backend = BACKEND_OPENHAPTICS;
	info.path = MISSING_LIBRARY;
	CHECK(open_device(info, none).code() == StatusCode::NO_DEVICE);
	CHECK(none == nullptr);
	CHECK(fake.misuse_count() == 0);
}
