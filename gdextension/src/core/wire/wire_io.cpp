#include "core/wire/wire_io.h"

#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace haptics {

namespace {

// Well-formed UTF-8 (RFC 3629): no overlong forms, no surrogates, nothing above U+10FFFF.
bool valid_utf8(const uint8_t *p_bytes, size_t p_size) {
	size_t i = 0;
	while (i < p_size) {
		const uint8_t lead = p_bytes[i];
		size_t extra = 0;
		uint32_t code = 0;
		if (lead < 0x80) {
			++i;
			continue;
		} else if ((lead & 0xE0) == 0xC0) {
			extra = 1;
			code = lead & 0x1F;
		} else if ((lead & 0xF0) == 0xE0) {
			extra = 2;
			code = lead & 0x0F;
		} else if ((lead & 0xF8) == 0xF0) {
			extra = 3;
			code = lead & 0x07;
		} else {
			return false;
		}
		if (i + extra >= p_size) {
			return false;
		}
		for (size_t k = 1; k <= extra; ++k) {
			if ((p_bytes[i + k] & 0xC0) != 0x80) {
				return false;
			}
			code = (code << 6) | (p_bytes[i + k] & 0x3F);
		}
		static constexpr uint32_t SMALLEST[] = { 0, 0x80, 0x800, 0x10000 };
		if (code < SMALLEST[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
			return false;
		}
		i += extra + 1;
	}
	return true;
}

} // namespace

void WireWriter::put(uint64_t p_value, int p_size) {
	for (int i = 0; i < p_size; ++i) {
		bytes_.push_back(static_cast<uint8_t>(p_value >> (8 * i)));
	}
}

void WireWriter::f32(float p_value) {
	uint32_t bits = 0;
	std::memcpy(&bits, &p_value, sizeof(bits));
	u32(bits);
}

void WireWriter::f64(double p_value) {
	uint64_t bits = 0;
	std::memcpy(&bits, &p_value, sizeof(bits));
	u64(bits);
}

void WireWriter::text(const std::string &p_value) {
	u16(static_cast<uint16_t>(p_value.size()));
	bytes_.insert(bytes_.end(), p_value.begin(), p_value.end());
}

WireReader::WireReader(std::span<const uint8_t> p_bytes, const char *p_what) :
		bytes_(p_bytes), path_(p_what) {}

Status WireReader::finish() {
	if (ok() && offset_ != bytes_.size()) {
		fail(StatusCode::INVALID_ARGUMENT, "%zu bytes more than the value holds", bytes_.size() - offset_);
	}
	return status_;
}

bool WireReader::need(size_t p_size) {
	if (!ok()) {
		return false;
	}
	if (bytes_.size() - offset_ < p_size) {
		fail(StatusCode::INVALID_ARGUMENT, "the bytes end early (%zu of %zu read)", offset_, bytes_.size());
		return false;
	}
	return true;
}

uint64_t WireReader::get(int p_size) {
	if (!need(static_cast<size_t>(p_size))) {
		return 0;
	}
	uint64_t value = 0;
	for (int i = 0; i < p_size; ++i) {
		value |= static_cast<uint64_t>(bytes_[offset_ + i]) << (8 * i);
	}
	offset_ += static_cast<size_t>(p_size);
	return value;
}

uint8_t WireReader::u8() {
	return static_cast<uint8_t>(get(1));
}

float WireReader::f32() {
	const uint32_t bits = u32();
	float value = 0.0f;
	std::memcpy(&value, &bits, sizeof(value));
	return value;
}

double WireReader::f64() {
	const uint64_t bits = u64();
	double value = 0.0;
	std::memcpy(&value, &bits, sizeof(value));
	return value;
}

std::string WireReader::text(uint32_t p_max_bytes) {
	const uint16_t size = u16();
	if (!ok()) {
		return {};
	}
	if (size > p_max_bytes) {
		fail(StatusCode::OUT_OF_RANGE, "%u bytes of text, at most %u", unsigned(size), unsigned(p_max_bytes));
		return {};
	}
	if (!need(size)) {
		return {};
	}
	const uint8_t *start = bytes_.data() + offset_;
	offset_ += size;
	if (!valid_utf8(start, size)) {
		fail(StatusCode::INVALID_ARGUMENT, "not UTF-8 text");
		return {};
	}
	return std::string(reinterpret_cast<const char *>(start), size);
}

void WireReader::enter(const char *p_name) {
	marks_.push_back(path_.size());
	path_ += '.';
	path_ += p_name;
}

void WireReader::enter_item(size_t p_index) {
	marks_.push_back(path_.size());
	path_ += '[' + std::to_string(p_index) + ']';
}

void WireReader::leave() {
	if (!marks_.empty()) {
		path_.resize(marks_.back());
		marks_.pop_back();
	}
}

void WireReader::fail(StatusCode p_code, const char *p_format, ...) {
	if (!ok()) {
		return;
	}
	char message[Status::MESSAGE_CAPACITY];
	va_list args;
	va_start(args, p_format);
	std::vsnprintf(message, sizeof(message), p_format, args);
	va_end(args);
	status_ = Status::error(p_code, "%s: %s", path_.c_str(), message);
}

} // namespace haptics
