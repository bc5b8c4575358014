#include "devices/hid/report_bits.h"

namespace haptics::hid {

namespace {

bool element_in_buffer(size_t p_buffer_size, const Field &p_field, uint32_t p_index, uint32_t &r_bit_offset) {
	if (p_field.bit_size == 0 || p_field.bit_size > 32 || p_index >= p_field.count) {
		return false;
	}
	const uint64_t offset = p_field.bit_offset + static_cast<uint64_t>(p_index) * p_field.bit_size;
	if (offset + p_field.bit_size > static_cast<uint64_t>(p_buffer_size) * 8) {
		return false;
	}
	r_bit_offset = static_cast<uint32_t>(offset);
	return true;
}

} // namespace

bool extract_bits(std::span<const uint8_t> p_buffer, uint32_t p_bit_offset, uint32_t p_bit_size, uint32_t &r_value) {
	if (p_bit_size == 0 || p_bit_size > 32 ||
			static_cast<uint64_t>(p_bit_offset) + p_bit_size > static_cast<uint64_t>(p_buffer.size()) * 8) {
		return false;
	}
	uint64_t value = 0;
	const uint32_t first_byte = p_bit_offset / 8;
	const uint32_t last_byte = (p_bit_offset + p_bit_size - 1) / 8;
	for (uint32_t b = last_byte + 1; b-- > first_byte;) {
		value = (value << 8) | p_buffer[b];
	}
	value >>= p_bit_offset % 8;
	r_value = static_cast<uint32_t>(value & ((uint64_t{ 1 } << p_bit_size) - 1));
	return true;
}

bool insert_bits(std::span<uint8_t> p_buffer, uint32_t p_bit_offset, uint32_t p_bit_size, uint32_t p_value) {
	if (p_bit_size == 0 || p_bit_size > 32 ||
			static_cast<uint64_t>(p_bit_offset) + p_bit_size > static_cast<uint64_t>(p_buffer.size()) * 8) {
		return false;
	}
	const uint64_t mask = ((uint64_t{ 1 } << p_bit_size) - 1) << (p_bit_offset % 8);
	const uint64_t bits = (static_cast<uint64_t>(p_value) << (p_bit_offset % 8)) & mask;
	const uint32_t first_byte = p_bit_offset / 8;
	const uint32_t last_byte = (p_bit_offset + p_bit_size - 1) / 8;
	for (uint32_t b = first_byte; b <= last_byte; ++b) {
		const uint32_t shift = 8 * (b - first_byte);
		const uint8_t byte_mask = static_cast<uint8_t>(mask >> shift);
		p_buffer[b] = static_cast<uint8_t>((p_buffer[b] & ~byte_mask) | static_cast<uint8_t>(bits >> shift));
	}
	return true;
}

int64_t sign_extend(uint32_t p_value, uint32_t p_bit_size) {
	if (p_bit_size == 0 || p_bit_size >= 32) {
		return static_cast<int32_t>(p_value);
	}
	const uint32_t sign = 1u << (p_bit_size - 1);
	const uint32_t masked = p_value & ((1u << p_bit_size) - 1);
	return static_cast<int64_t>(masked ^ sign) - static_cast<int64_t>(sign);
}

bool field_fits(const Field &p_field, int64_t p_value) {
	if (p_field.bit_size == 0 || p_field.bit_size > 32) {
		return false;
	}
	if (p_field.is_signed()) {
		const int64_t half = int64_t{ 1 } << (p_field.bit_size - 1);
		return p_value >= -half && p_value < half;
	}
	return p_value >= 0 && p_value < (int64_t{ 1 } << p_field.bit_size);
}

bool read_field_value(std::span<const uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t &r_value) {
	uint32_t offset = 0;
	uint32_t raw = 0;
	if (!element_in_buffer(p_report.size(), p_field, p_index, offset) || !extract_bits(p_report, offset, p_field.bit_size, raw)) {
		return false;
	}
	r_value = p_field.is_signed() ? sign_extend(raw, p_field.bit_size) : static_cast<int64_t>(raw);
	return true;
}

bool write_field_value(std::span<uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t p_value) {
	uint32_t offset = 0;
	if (!element_in_buffer(p_report.size(), p_field, p_index, offset) || !field_fits(p_field, p_value)) {
		return false;
	}
	return insert_bits(p_report, offset, p_field.bit_size, static_cast<uint32_t>(static_cast<uint64_t>(p_value)));
}

Status read_field(std::span<const uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t &r_value) {
	if (!read_field_value(p_report, p_field, p_index, r_value)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"HID %s report %u: value %u of the field at bit %u (%u x %u bits) is not inside the %zu-byte report",
				report_type_name(p_field.type), p_field.report_id, p_index, p_field.bit_offset, p_field.count, p_field.bit_size,
				p_report.size());
	}
	return Status::success();
}

Status write_field(std::span<uint8_t> p_report, const Field &p_field, uint32_t p_index, int64_t p_value) {
	if (!field_fits(p_field, p_value)) {
		return Status::error(StatusCode::OUT_OF_RANGE, "HID %s report %u: %lld does not fit the %s %u-bit field at bit %u",
				report_type_name(p_field.type), p_field.report_id, static_cast<long long>(p_value),
				p_field.is_signed() ? "signed" : "unsigned", p_field.bit_size, p_field.bit_offset);
	}
	if (!write_field_value(p_report, p_field, p_index, p_value)) {
		return Status::error(StatusCode::OUT_OF_RANGE,
				"HID %s report %u: value %u of the field at bit %u (%u x %u bits) is not inside the %zu-byte report",
				report_type_name(p_field.type), p_field.report_id, p_index, p_field.bit_offset, p_field.count, p_field.bit_size,
				p_report.size());
	}
	return Status::success();
}

} // namespace haptics::hid
