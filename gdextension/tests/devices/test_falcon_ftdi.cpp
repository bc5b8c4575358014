// FTDI facts (docs/devices/falcon.md): baud divisor encoding, status-byte stripping (never past the
// buffer), and the USB seam's result names, DeviceIo mapping and refusal of counts larger
// than the buffer; the libusb path parser.

#include "devices/falcon/falcon_ftdi.h"
#include "devices/usb/libusb_transport.h"
#include "devices/usb/usb_transport.h"

#include <doctest/doctest.h>

#include <cstring>
#include <span>
#include <vector>

using namespace haptics;
using namespace haptics::falcon;

TEST_CASE("falcon ftdi: NIF's baud constants encode the rates docs/devices/falcon.md derives") {
	CHECK(ftdi_decoded_baud(FTDI_BAUD_BOOTSTRAP) == doctest::Approx(9600.0).epsilon(1e-12));
	CHECK(ftdi_decoded_baud(FTDI_BAUD_FIRMWARE_UPLOAD) == doctest::Approx(3e6 / 21.0)); // 142 857 Bd.
	CHECK(ftdi_decoded_baud(FTDI_BAUD_NORMAL) == doctest::Approx(1.5e6));
	CHECK(ftdi_decoded_baud(FtdiBaud{ 0, 0 }) == 3e6);
	CHECK(ftdi_decoded_baud(FtdiBaud{ 1, 0 }) == 2e6);
}

TEST_CASE("falcon ftdi: baud encoding, 9600 -> 0x4138/0, 140000 -> 0x0015/1 (libftdi's rule)") {
	FtdiBaud baud;
	double actual = 0.0;
	REQUIRE(ftdi_encode_baud(9600, baud, actual));
	CHECK(baud == FTDI_BAUD_BOOTSTRAP);
	CHECK(actual == doctest::Approx(9600.0));
	REQUIRE(ftdi_encode_baud(140000, baud, actual));
	CHECK(baud.value == 0x0015);
	CHECK(baud.index == 0x0001); // 21 + 3/8: the fraction code 4 sets wIndex bit 0.
	CHECK(actual == doctest::Approx(140351.0).epsilon(1e-5));
	CHECK(ftdi_decoded_baud(baud) == doctest::Approx(actual));
	REQUIRE(ftdi_encode_baud(1500000, baud, actual));
	CHECK(baud == FTDI_BAUD_NORMAL);
	REQUIRE(ftdi_encode_baud(3000000, baud, actual));
	CHECK(baud == FtdiBaud{ 0, 0 });
	REQUIRE(ftdi_encode_baud(2000000, baud, actual));
	CHECK(baud == FtdiBaud{ 1, 0 });
	const Status low = ftdi_encode_baud(100, baud, actual);
	CHECK(low.code() == StatusCode::OUT_OF_RANGE);
	CHECK(std::strstr(low.message(), "got 100") != nullptr);
}

TEST_CASE("falcon ftdi: status bytes are stripped per 64-byte packet") {
	std::vector<uint8_t> in(64 + 64 + 10);
	for (size_t i = 0; i < in.size(); ++i) {
		in[i] = static_cast<uint8_t>(i);
	}
	uint8_t out[256];
	size_t overflow = 99;
	const size_t n = ftdi_strip_status(in, in.size(), out, sizeof(out), &overflow);
	CHECK(n == 62 + 62 + 8);
	CHECK(overflow == 0);
	CHECK(out[0] == 2);
	CHECK(out[61] == 63);
	CHECK(out[62] == 66); // Bytes 64, 65 were the second packet's status.
	CHECK(out[124] == 130);
	// A last packet of 1 byte holds no payload; a small output counts the overflow.
	CHECK(ftdi_strip_status(in, 65, out, sizeof(out)) == 62);
	CHECK(ftdi_strip_status(in, 64, out, 10, &overflow) == 10);
	CHECK(overflow == 52);
	CHECK(ftdi_strip_status(in, 2, out, sizeof(out)) == 0);
	// A length past the buffer (a transport's word) stops at the buffer's end.
	const std::span<const uint8_t> first_packet(in.data(), 64);
	CHECK(ftdi_strip_status(first_packet, 4096, out, sizeof(out), &overflow) == 62);
	CHECK(overflow == 0);
	CHECK(out[61] == 63);
}

namespace {

// Reports whatever count it is told, whatever the buffer: a broken driver or fake.
class MiscountingTransport final : public usb::UsbTransport {
public:
	int32_t reported = 0;
	const char *describe() const override { return "miscounting"; }

private:
	usb::UsbTransfer raw_control_transfer(uint8_t, uint8_t, uint16_t, uint16_t, uint8_t *, uint16_t, uint32_t) override {
		return { usb::UsbResult::OK, reported };
	}
	usb::UsbTransfer raw_bulk_write(uint8_t, const uint8_t *, int32_t, uint32_t) override { return { usb::UsbResult::OK, reported }; }
	usb::UsbTransfer raw_bulk_read(uint8_t, uint8_t *, int32_t, uint32_t) override { return { usb::UsbResult::OK, reported }; }
};

} // namespace

TEST_CASE("falcon usb seam: a count larger than the buffer is OVERFLOW with nothing transferred, a negative one OTHER") {
	MiscountingTransport transport;
	uint8_t buffer[FTDI_PACKET_SIZE] = {};
	const auto all = [&] {
		return std::vector<usb::UsbTransfer>{ transport.bulk_read(FALCON_ENDPOINT_IN, buffer, sizeof(buffer), 10),
			transport.bulk_write(FALCON_ENDPOINT_OUT, buffer, sizeof(buffer), 10),
			transport.control_transfer(usb::USB_REQUEST_TYPE_VENDOR_IN, 0x90, 0, 0, buffer, sizeof(buffer), 10) };
	};
	transport.reported = FTDI_PACKET_SIZE;
	for (const usb::UsbTransfer &transfer : all()) {
		CHECK(transfer.result == usb::UsbResult::OK);
		CHECK(transfer.transferred == FTDI_PACKET_SIZE);
	}
	transport.reported = FTDI_PACKET_SIZE + 1;
	for (const usb::UsbTransfer &transfer : all()) {
		CHECK(transfer.result == usb::UsbResult::OVERFLOW);
		CHECK(transfer.transferred == 0);
	}
	transport.reported = -5;
	for (const usb::UsbTransfer &transfer : all()) {
		CHECK(transfer.result == usb::UsbResult::OTHER);
		CHECK(transfer.transferred == 0);
	}
	// Without a data stage nothing can have been transferred.
	transport.reported = 1;
	CHECK(ftdi_send(transport, FtdiRequest{ FTDI_REQUEST_RESET, FTDI_PURGE_RX, 0 }).result == usb::UsbResult::OVERFLOW);
	CHECK(std::strcmp(usb::usb_result_name(usb::UsbResult::OVERFLOW), "LIBUSB_ERROR_OVERFLOW") == 0);
}

TEST_CASE("falcon usb seam: result names are libusb's, NO_DEVICE means DISCONNECTED") {
	CHECK(std::strcmp(usb::usb_result_name(usb::UsbResult::NO_DEVICE), "LIBUSB_ERROR_NO_DEVICE") == 0);
	CHECK(std::strcmp(usb::usb_result_name(usb::UsbResult::ACCESS), "LIBUSB_ERROR_ACCESS") == 0);
	CHECK(std::strcmp(usb::usb_result_name(usb::UsbResult::TIMEOUT), "LIBUSB_ERROR_TIMEOUT") == 0);
	CHECK(std::strcmp(usb::usb_result_name(usb::UsbResult::OK), "LIBUSB_SUCCESS") == 0);
	CHECK(usb::usb_result_io(usb::UsbResult::NO_DEVICE) == DeviceIo::DISCONNECTED);
	CHECK(usb::usb_result_io(usb::UsbResult::PIPE) == DeviceIo::FAILED);
	CHECK(usb::usb_result_io(usb::UsbResult::TIMEOUT) == DeviceIo::FAILED);
	CHECK(usb::usb_result_io(usb::UsbResult::OK) == DeviceIo::OK);
	// libusb's codes map one to one.
	CHECK(usb::usb_result_from_libusb(-4) == usb::UsbResult::NO_DEVICE);
	CHECK(usb::usb_result_from_libusb(-3) == usb::UsbResult::ACCESS);
	CHECK(usb::usb_result_from_libusb(-7) == usb::UsbResult::TIMEOUT);
	CHECK(usb::usb_result_from_libusb(-99) == usb::UsbResult::OTHER);
	CHECK(usb::usb_result_from_libusb(12) == usb::UsbResult::OK);
}

TEST_CASE("falcon usb seam: port paths as device enumeration writes them") {
	usb::UsbPortPath path;
	REQUIRE(usb::parse_usb_port_path("1-4.2.3", path));
	CHECK(path.bus == 1);
	CHECK(path.port_count == 3);
	CHECK(path.ports[0] == 4);
	CHECK(path.ports[2] == 3);
	CHECK(path.address == -1);
	REQUIRE(usb::parse_usb_port_path("3-root", path));
	CHECK(path.bus == 3);
	CHECK(path.port_count == 0);
	REQUIRE(usb::parse_usb_port_path("2-addr17", path));
	CHECK(path.address == 17);
	for (const char *bad : { "", "1", "-4", "1-", "1-4..2", "1-4.x", "300-1", "1-1.2.3.4.5.6.7.8", "1-addr", "1-addr999" }) {
		CAPTURE(bad);
		const Status status = usb::parse_usb_port_path(bad, path);
		CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	}
	const Status status = usb::parse_usb_port_path("bus-x", path);
	CHECK(std::strstr(status.message(), "'bus-x'") != nullptr);

	uint16_t vendor = 0;
	uint16_t product = 0;
	REQUIRE(usb::parse_usb_vid_pid("0403:CB48", vendor, product));
	CHECK(vendor == 0x0403);
	CHECK(product == 0xCB48);
	CHECK_FALSE(usb::parse_usb_vid_pid("0403", vendor, product));
	CHECK_FALSE(usb::parse_usb_vid_pid("0403:cb48x", vendor, product));
	CHECK_FALSE(usb::parse_usb_vid_pid("10403:cb48", vendor, product));
}
