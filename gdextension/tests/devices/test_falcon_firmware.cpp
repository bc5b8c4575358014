// The firmware-load sequence of docs/devices/falcon.md against the scripted FTDI bridge and loader: the
// exact control transfers and bulk payloads, both handshake reply shapes, 100 failed tries,
// echo mismatch, timeout, silence, split echoes, reads claiming more than their buffer; the
// firmware check; and the user's file.

#include "dev_tools/falcon/scripted_falcon.h"
#include "dev_tools/falcon/scripted_falcon_device.h"
#include "devices/falcon/falcon_backend.h"
#include "devices/falcon/falcon_firmware_loader.h"
#include "devices/falcon/falcon_ftdi.h"

#include "scratch_dir.h"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

using namespace haptics;
using namespace haptics::falcon;

namespace {

struct Rig {
	std::shared_ptr<ScriptedFalcon> model;
	std::unique_ptr<usb::UsbTransport> transport;
	explicit Rig(const ScriptedFalconOptions &p_options = {}) :
			model(std::make_shared<ScriptedFalcon>(p_options)) {
		REQUIRE(model->open_transport(transport));
	}
};

struct Control {
	uint8_t request;
	uint16_t value;
};

// docs/devices/falcon.md, "Loading the firmware", in order; all bmRequestType 0x40, wIndex 0.
const Control FIRMWARE_MODE_SEQUENCE[] = { { 0x00, 0x0001 }, { 0x00, 0x0002 }, { 0x09, 16 }, { 0x03, 0x4138 }, { 0x04, 0x0008 },
	{ 0x02, 0x0000 }, { 0x01, 0x0200 }, { 0x01, 0x0100 }, { 0x01, 0x0101 } };
const Control UPLOAD_START_SEQUENCE[] = { { 0x01, 0x0100 }, { 0x03, 0x0015 } };
const Control NORMAL_MODE_SEQUENCE[] = { { 0x09, 1 }, { 0x03, 0x0002 }, { 0x00, 0x0001 }, { 0x00, 0x0002 } };

void check_controls(const std::vector<ControlRecord> &p_records, const std::vector<Control> &p_expected) {
	REQUIRE(p_records.size() == p_expected.size());
	for (size_t i = 0; i < p_expected.size(); ++i) {
		CAPTURE(i);
		CHECK(p_records[i].request_type == 0x40);
		CHECK(p_records[i].request == p_expected[i].request);
		CHECK(p_records[i].value == p_expected[i].value);
		CHECK(p_records[i].index == 0);
	}
}

std::vector<Control> full_sequence() {
	std::vector<Control> all(std::begin(FIRMWARE_MODE_SEQUENCE), std::end(FIRMWARE_MODE_SEQUENCE));
	all.insert(all.end(), std::begin(UPLOAD_START_SEQUENCE), std::end(UPLOAD_START_SEQUENCE));
	all.insert(all.end(), std::begin(NORMAL_MODE_SEQUENCE), std::end(NORMAL_MODE_SEQUENCE));
	return all;
}

// A file holding p_bytes in a folder of its own (scratch_dir.h).
struct TempFile {
	testing::ScratchDir dir{ "haptics-falcon-fw" };
	std::filesystem::path path = dir / "firmware.bin";
	explicit TempFile(const std::vector<uint8_t> &p_bytes) {
		std::ofstream out(path, std::ios::binary);
		out.write(reinterpret_cast<const char *>(p_bytes.data()), static_cast<std::streamsize>(p_bytes.size()));
	}
};

} // namespace

TEST_CASE("falcon firmware: the full load sequence, Linux reply, byte for byte") {
	Rig rig;
	const std::vector<uint8_t> image = make_test_firmware_image(7914);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	const Status status = loader.run();
	REQUIRE_MESSAGE(status, status.message());
	CHECK(loader.report().stage == FirmwareStage::DONE);
	CHECK(loader.report().handshake_tries == 1);
	CHECK_FALSE(loader.report().apple_reply);
	CHECK(loader.report().bytes_sent == 7914);
	CHECK(loader.report().chunks_sent == 128); // 127 x 62 + 40.

	check_controls(rig.model->control_transfers(), full_sequence());
	const std::vector<BulkRecord> writes = rig.model->bulk_writes();
	REQUIRE(writes.size() == 2 + 128);
	CHECK(writes[0].endpoint == 0x02);
	CHECK(writes[0].bytes == std::vector<uint8_t>{ 0x0A, 0x43, 0x0D });
	CHECK(writes[1].bytes == std::vector<uint8_t>{ 0x41 });
	for (size_t chunk = 0; chunk < 128; ++chunk) {
		CHECK(writes[2 + chunk].bytes.size() == (chunk < 127 ? 62u : 40u));
	}
	CHECK(rig.model->uploaded_image() == image);
	CHECK(rig.model->firmware_running());
	// Every IN read asked for one whole 64-byte packet and got the status bytes first.
	for (const BulkRecord &read : rig.model->bulk_reads()) {
		CHECK(read.endpoint == 0x81);
		REQUIRE(read.bytes.size() >= 2);
		CHECK(read.bytes[0] == 0x31);
	}
}

TEST_CASE("falcon firmware: the 7-byte 'Apple' handshake reply is accepted too") {
	ScriptedFalconOptions options;
	options.handshake_reply = HandshakeReply::APPLE;
	Rig rig(options);
	const std::vector<uint8_t> image = make_test_firmware_image(500);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	REQUIRE(loader.run());
	CHECK(loader.report().apple_reply);
	const std::vector<BulkRecord> reads = rig.model->bulk_reads();
	REQUIRE_FALSE(reads.empty());
	CHECK(reads[0].bytes == std::vector<uint8_t>{ 0x31, 0x60, 0x00, 0x0A, 0x44, 0x2C, 0x0D });
}

TEST_CASE("falcon firmware: wrong handshake replies are retried - 100 tries then a clear error") {
	ScriptedFalconOptions options;
	options.handshake_failures = 5;
	{
		Rig rig(options);
		const std::vector<uint8_t> image = make_test_firmware_image(100);
		FirmwareLoader loader(*rig.transport, image.data(), image.size());
		REQUIRE(loader.run());
		CHECK(loader.report().handshake_tries == 6);
	}
	options.handshake_failures = -1; // Never answers.
	Rig rig(options);
	const std::vector<uint8_t> image = make_test_firmware_image(100);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	const Status status = loader.run();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::strstr(status.message(), "in 100 tries") != nullptr);
	CHECK(loader.report().stage == FirmwareStage::FAILED);
	CHECK(loader.report().handshake_tries == 100);
	size_t queries = 0;
	for (const BulkRecord &write : rig.model->bulk_writes()) {
		queries += write.bytes == std::vector<uint8_t>{ 0x0A, 0x43, 0x0D } ? 1 : 0;
	}
	CHECK(queries == 100);
	CHECK(rig.model->uploaded_image().empty());
	// A failed loader stays failed.
	CHECK(loader.step().code() == StatusCode::INVALID_STATE);
}

TEST_CASE("falcon firmware: an echo with one wrong byte is a checksum mismatch naming the byte") {
	ScriptedFalconOptions options;
	options.echo = EchoMode::CORRUPT;
	options.corrupt_at = 100;
	Rig rig(options);
	const std::vector<uint8_t> image = make_test_firmware_image(1000);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	const Status status = loader.run();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	char expected[96];
	std::snprintf(expected, sizeof(expected), "checksum mismatch at image byte 100 (sent 0x%02X, echoed 0x%02X)", image[100],
			image[100] ^ 0xFF);
	CHECK_MESSAGE(std::strstr(status.message(), expected) != nullptr, status.message());
	CHECK(loader.report().bytes_sent == 62); // Chunk 0 went through; chunk 1 holds byte 100.
	CHECK_FALSE(rig.model->firmware_running());
}

TEST_CASE("falcon firmware: echo timeout and echo silence are errors, not hangs") {
	for (const EchoMode mode : { EchoMode::TIMEOUT, EchoMode::SILENT }) {
		ScriptedFalconOptions options;
		options.echo = mode;
		Rig rig(options);
		const std::vector<uint8_t> image = make_test_firmware_image(300);
		FirmwareLoadOptions load;
		load.max_empty_reads = 20;
		FirmwareLoader loader(*rig.transport, image.data(), image.size(), load);
		const Status status = loader.run();
		CHECK(status.code() == StatusCode::DEVICE_ERROR);
		if (mode == EchoMode::TIMEOUT) {
			CHECK_MESSAGE(std::strstr(status.message(), "firmware upload: a chunk's echo failed: LIBUSB_ERROR_TIMEOUT") != nullptr,
					status.message());
		} else {
			CHECK_MESSAGE(std::strstr(status.message(), "no reply to a chunk's echo after 20 empty reads") != nullptr, status.message());
		}
		CHECK(loader.report().bytes_sent == 0);
	}
}

TEST_CASE("falcon firmware: echoes split across reads (30 + 32, and 7-byte pieces) still verify") {
	ScriptedFalconOptions options;
	options.echo = EchoMode::SPLIT;
	options.echo_split_at = 30;
	{
		Rig rig(options);
		const std::vector<uint8_t> image = make_test_firmware_image(7914, 7);
		FirmwareLoader loader(*rig.transport, image.data(), image.size());
		REQUIRE(loader.run());
		CHECK(rig.model->uploaded_image() == image);
		// The first chunk's echo came as 2 + 30 and 2 + 32 bytes.
		const std::vector<BulkRecord> reads = rig.model->bulk_reads();
		REQUIRE(reads.size() > 4);
		CHECK(reads[2].bytes.size() == 32);
		CHECK(reads[3].bytes.size() == 34);
	}
	options.echo = EchoMode::WHOLE;
	options.max_reply_payload = 7;
	Rig rig(options);
	const std::vector<uint8_t> image = make_test_firmware_image(1000, 9);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	REQUIRE(loader.run());
	CHECK(rig.model->uploaded_image() == image);
}

TEST_CASE("falcon firmware: step() walks the stages in order") {
	Rig rig;
	const std::vector<uint8_t> image = make_test_firmware_image(130); // 62 + 62 + 6.
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	const FirmwareStage expected[] = { FirmwareStage::HANDSHAKE, FirmwareStage::UPLOAD_START, FirmwareStage::UPLOAD,
		FirmwareStage::UPLOAD, FirmwareStage::UPLOAD, FirmwareStage::NORMAL_MODE, FirmwareStage::DONE };
	for (const FirmwareStage stage : expected) {
		REQUIRE(loader.step());
		CHECK(std::strcmp(firmware_stage_name(loader.report().stage), firmware_stage_name(stage)) == 0);
	}
	CHECK(loader.report().chunks_sent == 3);
	CHECK(loader.step()); // DONE stays DONE.
}

TEST_CASE("falcon firmware: unplugging mid-upload is DEVICE_DISCONNECTED with the USB error") {
	Rig rig;
	const std::vector<uint8_t> image = make_test_firmware_image(1000);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	for (int i = 0; i < 5; ++i) {
		REQUIRE(loader.step());
	}
	rig.model->unplug();
	const Status status = loader.step();
	CHECK(status.code() == StatusCode::DEVICE_DISCONNECTED);
	CHECK(std::strstr(status.message(), "LIBUSB_ERROR_NO_DEVICE") != nullptr);
}

TEST_CASE("falcon firmware: an empty or oversized image is refused before any transfer") {
	Rig rig;
	FirmwareLoader empty(*rig.transport, nullptr, 0);
	CHECK(std::strstr(empty.run().message(), "is empty") != nullptr);
	std::vector<uint8_t> huge(FIRMWARE_MAX_SIZE + 1, 0x55);
	FirmwareLoader large(*rig.transport, huge.data(), huge.size());
	CHECK(std::strstr(large.run().message(), "larger than 65536 bytes") != nullptr);
	CHECK(rig.model->control_transfers().empty());
}

TEST_CASE("falcon firmware: the firmware check sees a framed reply only once the firmware runs") {
	Rig rig;
	bool loaded = true;
	REQUIRE(falcon_probe_firmware(*rig.transport, 5, 10, loaded));
	CHECK_FALSE(loaded);
	const std::vector<uint8_t> image = make_test_firmware_image(200);
	FirmwareLoader loader(*rig.transport, image.data(), image.size());
	REQUIRE(loader.run());
	REQUIRE(falcon_probe_firmware(*rig.transport, 5, 10, loaded));
	CHECK(loaded);
	rig.model->unplug();
	CHECK(falcon_probe_firmware(*rig.transport, 5, 10, loaded).code() == StatusCode::DEVICE_DISCONNECTED);
}

TEST_CASE("falcon firmware: reads claiming more bytes than their buffer are refused, not stripped past it") {
	ScriptedFalconOptions options;
	options.overstated_read_bytes = 4 * FTDI_PACKET_SIZE;
	Rig loading(options);
	const std::vector<uint8_t> image = make_test_firmware_image(200);
	FirmwareLoader loader(*loading.transport, image.data(), image.size());
	Status status = loader.run();
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::string(status.message()) == "Falcon loader handshake: reading the handshake reply failed: LIBUSB_ERROR_OVERFLOW");
	CHECK(loader.report().handshake_tries == 1);

	options.firmware_loaded = true;
	Rig running(options);
	bool loaded = true;
	status = falcon_probe_firmware(*running.transport, 5, 10, loaded);
	CHECK(status.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::string(status.message()) == "Falcon firmware check: read failed: LIBUSB_ERROR_OVERFLOW");
	CHECK_FALSE(loaded);
}

TEST_CASE("falcon firmware: the user's file, with messages that say what to do") {
	std::vector<uint8_t> image;
	Status status = read_firmware_file("", image);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "firmware file not set: set HAPTICS_FALCON_FIRMWARE to Novint's firmware file (not shipped with this game)") != nullptr);

	status = read_firmware_file("/nonexistent/novint.bin", image);
	CHECK(std::strstr(status.message(), "'/nonexistent/novint.bin' not found or unreadable (No such file or directory)") != nullptr);
	CHECK(std::strstr(status.message(), "HAPTICS_FALCON_FIRMWARE") != nullptr);

	status = read_firmware_file(std::filesystem::temp_directory_path().string(), image);
	CHECK(std::strstr(status.message(), "could not be read") != nullptr);

	{
		const TempFile empty({});
		status = read_firmware_file(empty.path.string(), image);
		CHECK(std::strstr(status.message(), "is empty") != nullptr);
	}
	{
		const TempFile huge(std::vector<uint8_t>(FIRMWARE_MAX_SIZE + 10, 1));
		status = read_firmware_file(huge.path.string(), image);
		CHECK(std::strstr(status.message(), "not a Falcon image") != nullptr);
	}
	CHECK(image.empty()); // Untouched by every failure.
	const std::vector<uint8_t> content = make_test_firmware_image(7324);
	const TempFile good(content);
	REQUIRE(read_firmware_file(good.path.string(), image));
	CHECK(image == content);
}
