// The schema values' wire format (core/wire/codec.h, docs/values.md): what goes in comes back
// out, the game's 2D vectors are flipped into device space, and every malformed or hostile
// byte string is refused by name without touching the value it was to fill.

#include "core/device/device.h"
#include "core/render/force_components.h"
#include "core/render/frame.h"
#include "core/wire/codec.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace haptics;

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool mentions(const Status &p_status, const char *p_text) {
	return std::strstr(p_status.message(), p_text) != nullptr;
}

Frame sample_frame() {
	Frame frame;
	frame.sequence = 42;
	frame.time_s = 1.25;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	add_contact(frame, { -1.0, 0.0, 0.0 }, ContactMaterial{ 4.0, 0.5 });
	add_resting(frame, { 0.0, -1.0, 0.0 }, 2.5);
	set_water(frame, true, 0.3, -0.2);
	frame.velocity_m_per_s = { 1.5, -2.0, 0.0 };
	return frame;
}

void check_same(const Frame &p_a, const Frame &p_b) {
	CHECK(p_a.sequence == p_b.sequence);
	CHECK(p_a.time_s == p_b.time_s);
	REQUIRE(p_a.contacts.size() == p_b.contacts.size());
	for (size_t i = 0; i < p_a.contacts.size(); ++i) {
		CHECK(p_a.contacts[i].normal == p_b.contacts[i].normal);
		REQUIRE(p_a.contacts[i].material.has_value() == p_b.contacts[i].material.has_value());
		if (p_a.contacts[i].material) {
			CHECK(p_a.contacts[i].material->stiffness_n == p_b.contacts[i].material->stiffness_n);
			CHECK(p_a.contacts[i].material->friction_n == p_b.contacts[i].material->friction_n);
		}
	}
	REQUIRE(p_a.resting.size() == p_b.resting.size());
	CHECK(p_a.resting[0].mass_kg == p_b.resting[0].mass_kg);
	CHECK(p_a.in_water == p_b.in_water);
	CHECK(p_a.water_drag_n_s_per_m == p_b.water_drag_n_s_per_m);
	CHECK(p_a.water_inertia_n == p_b.water_inertia_n);
	CHECK(p_a.velocity_m_per_s == p_b.velocity_m_per_s);
}

double f64_at(const std::vector<uint8_t> &p_bytes, size_t p_offset) {
	double value = 0.0;
	std::memcpy(&value, p_bytes.data() + p_offset, sizeof(value));
	return value;
}

template <typename T>
Status decode_bytes(const std::vector<uint8_t> &p_bytes, T &r_value) {
	return decode(std::span<const uint8_t>(p_bytes.data(), p_bytes.size()), r_value);
}

} // namespace

TEST_CASE("wire: a frame comes back as it went, materials present or not") {
	const Frame sent = sample_frame();
	Frame received;
	REQUIRE(decode_bytes(encode(sent), received));
	check_same(sent, received);
	CHECK_FALSE(received.contacts[0].material.has_value());
	CHECK(received.contacts[1].material.has_value());
}

TEST_CASE("wire: a 2D game vector travels in game axes and arrives in device space") {
	Contact contact;
	contact.normal = { 0.25, 1.0, 0.0 }; // Device: up.
	const std::vector<uint8_t> bytes = encode(contact);
	// Layout id, then the normal as two f64: x, and y flipped (game axes point down).
	REQUIRE(bytes.size() == 4 + 16 + 1);
	CHECK(f64_at(bytes, 4) == 0.25);
	CHECK(f64_at(bytes, 12) == -1.0);
	CHECK(bytes[20] == 0); // No material.
	Contact back;
	REQUIRE(decode_bytes(bytes, back));
	CHECK(back.normal == Vec3{ 0.25, 1.0, 0.0 });
}

TEST_CASE("wire: bytes of another layout are refused as out of step") {
	std::vector<uint8_t> bytes = encode(sample_frame());
	bytes[0] ^= 0x01;
	Frame received;
	const Status status = decode_bytes(bytes, received);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "HapticFrame"));
	CHECK(mentions(status, "out of step"));
	// A Contact's bytes are not a Frame's either.
	CHECK_FALSE(decode_bytes(encode(Contact{ { 0.0, 1.0, 0.0 }, std::nullopt }), received));
}

TEST_CASE("wire: every truncation and any trailing byte is refused, and the value is untouched") {
	const std::vector<uint8_t> bytes = encode(sample_frame());
	Frame untouched;
	untouched.sequence = 7;
	for (size_t size = 0; size < bytes.size(); ++size) {
		CAPTURE(size);
		Frame received = untouched;
		const Status status = decode_bytes(std::vector<uint8_t>(bytes.begin(), bytes.begin() + size), received);
		CHECK_FALSE(status.ok());
		CHECK(received.sequence == 7);
		CHECK(received.contacts.empty());
	}
	std::vector<uint8_t> longer = bytes;
	longer.push_back(0);
	Frame received;
	const Status status = decode_bytes(longer, received);
	CHECK(mentions(status, "1 bytes more than the value holds"));
}

TEST_CASE("wire: limits from the schema are checked on the way in, naming the field") {
	struct Case {
		Frame frame;
		StatusCode code;
		const char *field;
	};
	Frame nan_normal = sample_frame();
	nan_normal.contacts[1].normal.x = NaN;
	Frame zero_normal = sample_frame();
	zero_normal.contacts[0].normal = {};
	Frame stiff = sample_frame();
	stiff.contacts[1].material->stiffness_n = MAX_GAIN * 2.0;
	Frame heavy = sample_frame();
	heavy.resting[0].mass_kg = -1.0;
	Frame fast = sample_frame();
	fast.velocity_m_per_s = { MAX_SPEED_M_PER_S * 2.0, 0.0, 0.0 };
	const Case cases[] = {
		{ nan_normal, StatusCode::INVALID_ARGUMENT, "HapticFrame.contacts[1].normal: not finite" },
		{ zero_normal, StatusCode::INVALID_ARGUMENT, "HapticFrame.contacts[0].normal: zero length" },
		{ stiff, StatusCode::OUT_OF_RANGE, "HapticFrame.contacts[1].material.stiffness_n: 200 is outside [0, 100]" },
		{ heavy, StatusCode::OUT_OF_RANGE, "HapticFrame.resting[0].mass_kg" },
		{ fast, StatusCode::OUT_OF_RANGE, "HapticFrame.velocity_m_per_s: length 2000 is above 1000" },
	};
	for (const Case &c : cases) {
		CAPTURE(c.field);
		Frame received;
		const Status status = decode_bytes(encode(c.frame), received);
		CAPTURE(status.message());
		CHECK(status.code() == c.code);
		CHECK(mentions(status, c.field));
		// The same limits for a value made in C++.
		CHECK(mentions(check_fields(c.frame), c.field));
	}
	CHECK(check_fields(sample_frame()));
}

TEST_CASE("wire: hostile counts, flags and indices are refused before anything is read past them") {
	std::vector<uint8_t> bytes = encode(Frame{});
	// Frame{}: id (4), sequence (8), time_s (8), then the contacts' u32 count.
	bytes[20] = 17;
	Frame frame;
	CHECK(mentions(decode_bytes(bytes, frame), "HapticFrame.contacts: 17 items, at most 16"));

	std::vector<uint8_t> flag = encode(Contact{ { 0.0, 1.0, 0.0 }, std::nullopt });
	flag.back() = 2;
	Contact contact;
	CHECK(mentions(decode_bytes(flag, contact), "HapticContact.material: 2 is not a presence flag"));

	Frame dry;
	std::vector<uint8_t> water = encode(dry);
	water[4 + 8 + 8 + 4 + 4] = 3; // in_water.
	CHECK(mentions(decode_bytes(water, frame), "HapticFrame.in_water: 3 is not a bool"));

	std::vector<uint8_t> io = encode(DeviceStatus{});
	io[4] = 7;
	DeviceStatus status;
	CHECK(mentions(decode_bytes(io, status), "HapticDeviceStatus.io: 7 is none of the 3 values"));
}

TEST_CASE("wire: text is UTF-8 within its length, both checked") {
	DeviceStatus status;
	status.io = DeviceIo::FAILED;
	status.reason.assign("USB transfer failed: é");
	DeviceStatus back;
	REQUIRE(decode_bytes(encode(status), back));
	CHECK(back.reason.view() == "USB transfer failed: é");

	std::vector<uint8_t> bytes = encode(status);
	const uint8_t e_acute[] = { 0xC3, 0xA9 };
	const auto e_at = std::search(bytes.begin(), bytes.end(), std::begin(e_acute), std::end(e_acute));
	REQUIRE(e_at != bytes.end());
	*(e_at + 1) = 0xFF; // The é's last byte: no longer UTF-8.
	CHECK(mentions(decode_bytes(bytes, back), "HapticDeviceStatus.reason: not UTF-8 text"));

	std::vector<uint8_t> long_text = { bytes.begin(), bytes.begin() + 5 }; // id and io.
	long_text.push_back(200); // 200 bytes of text...
	long_text.push_back(0);
	long_text.resize(long_text.size() + 200, 'a');
	CHECK(mentions(decode_bytes(long_text, back), "200 bytes of text, at most 159"));
	// A FixedString never ends inside a UTF-8 sequence when text is cut to fit.
	FixedString<4> cut("abcé");
	CHECK(cut.view() == "abc");
}

TEST_CASE("wire: a fixed array holds exactly its count") {
	ForceComponents forces;
	forces.parts[0] = { 0.0, 2.0, 0.0 };
	ForceComponents back;
	REQUIRE(decode_bytes(encode(forces), back));
	CHECK(back.parts[0] == Vec3{ 0.0, 2.0, 0.0 });
	std::vector<uint8_t> bytes = encode(forces);
	bytes[4] = 4; // The parts' count.
	CHECK(mentions(decode_bytes(bytes, back), "HapticForces.parts: 4 items, exactly 5"));
}

TEST_CASE("wire: random corruptions are refused or decode to a value that encodes to the same bytes") {
	const std::vector<uint8_t> valid = encode(sample_frame());
	std::mt19937 random(20261128);
	std::uniform_int_distribution<size_t> position(0, valid.size() - 1);
	std::uniform_int_distribution<int> byte(0, 255);
	int accepted = 0;
	for (int trial = 0; trial < 20000; ++trial) {
		std::vector<uint8_t> bytes = valid;
		const int flips = 1 + trial % 4;
		for (int f = 0; f < flips; ++f) {
			bytes[position(random)] = static_cast<uint8_t>(byte(random));
		}
		if (trial % 7 == 0) {
			bytes.resize(position(random));
		}
		Frame received;
		if (decode_bytes(bytes, received)) {
			++accepted;
			CHECK(encode(received) == bytes);
			CHECK(check_fields(received));
		}
	}
	MESSAGE("random corruptions accepted as other valid frames: ", accepted, " of 20000");
}
