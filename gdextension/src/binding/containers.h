// Engine containers as thin owners of a Variant of the right type: Dictionary and Array
// share their data like the engine's own, packed arrays copy on write.
#pragma once

#include <cstdint>
#include <string_view>
#include <utility>

#include "binding/variant.h"

namespace gd {

class Array;

class Dictionary {
public:
	Dictionary();
	// Adopts p_value, which must hold a Dictionary (checked by the caller's type dispatch).
	explicit Dictionary(Variant p_value) :
			value_(std::move(p_value)) {}

	void set(const Variant &p_key, const Variant &p_value);
	// False, leaving r_value untouched, when the key is missing.
	bool get(const Variant &p_key, Variant &r_value) const;
	bool has(const Variant &p_key) const;
	int64_t size() const;
	Array keys() const;

	const Variant &variant() const { return value_; }

private:
	Variant value_;
};

class Array {
public:
	Array();
	explicit Array(Variant p_value) :
			value_(std::move(p_value)) {}

	void append(const Variant &p_value);
	int64_t size() const;
	// Nil when p_index is out of range.
	Variant get(int64_t p_index) const;

	const Variant &variant() const { return value_; }

private:
	Variant value_;
};

// Strings, appended one by one (names and messages: a handful at a time).
class PackedStringArray {
public:
	PackedStringArray();
	explicit PackedStringArray(Variant p_value) :
			value_(std::move(p_value)) {}

	void append(std::string_view p_text);
	int64_t size() const;

	const Variant &variant() const { return value_; }

private:
	Variant value_;
};

// Packed arrays of plain values, written through one pointer after a single resize.
template <typename T, VariantType TYPE>
class PackedArray {
public:
	PackedArray();
	explicit PackedArray(Variant p_value) :
			value_(std::move(p_value)) {}

	int64_t size() const;
	bool resize(int64_t p_size);
	// Contiguous storage; valid until the next resize. Null when empty.
	T *ptrw();
	const T *ptr() const;

	const Variant &variant() const { return value_; }

private:
	Variant value_;
};

using PackedByteArray = PackedArray<uint8_t, VariantType::PACKED_BYTE_ARRAY>;
using PackedFloat32Array = PackedArray<float, VariantType::PACKED_FLOAT32_ARRAY>;
using PackedVector2Array = PackedArray<Vector2, VariantType::PACKED_VECTOR2_ARRAY>;

template <>
uint8_t *PackedByteArray::ptrw();
template <>
const uint8_t *PackedByteArray::ptr() const;
template <>
float *PackedFloat32Array::ptrw();
template <>
const float *PackedFloat32Array::ptr() const;
template <>
Vector2 *PackedVector2Array::ptrw();
template <>
const Vector2 *PackedVector2Array::ptr() const;

extern template class PackedArray<uint8_t, VariantType::PACKED_BYTE_ARRAY>;
extern template class PackedArray<float, VariantType::PACKED_FLOAT32_ARRAY>;
extern template class PackedArray<Vector2, VariantType::PACKED_VECTOR2_ARRAY>;

} // namespace gd
