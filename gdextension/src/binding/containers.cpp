#include "binding/containers.h"

namespace gd {

namespace {

Variant make_default(VariantType p_type) {
	return Variant::from_engine([&](GDExtensionUninitializedVariantPtr r_dst) {
		GDExtensionCallError error{};
		api.variant_construct(static_cast<GDExtensionVariantType>(p_type), r_dst, nullptr, 0,
				&error);
	});
}

int64_t size_of(const Variant &p_value) {
	Variant ret;
	// `size` does not modify; variant_call only takes a mutable self.
	if (!const_cast<Variant &>(p_value).call("size", ret)) {
		return 0;
	}
	return ret.as_int();
}

} // namespace

Dictionary::Dictionary() :
		value_(make_default(VariantType::DICTIONARY)) {}

void Dictionary::set(const Variant &p_key, const Variant &p_value) {
	GDExtensionBool valid = 0;
	api.variant_set(const_cast<GDExtensionVariantPtr>(value_.ptr()), p_key.ptr(), p_value.ptr(),
			&valid);
}

bool Dictionary::get(const Variant &p_key, Variant &r_value) const {
	if (!has(p_key)) {
		return false;
	}
	GDExtensionBool valid = 0;
	Variant value = Variant::from_engine([&](GDExtensionUninitializedVariantPtr r_dst) {
		api.variant_get(value_.ptr(), p_key.ptr(), r_dst, &valid);
	});
	if (!valid) {
		return false;
	}
	r_value = std::move(value);
	return true;
}

bool Dictionary::has(const Variant &p_key) const {
	Variant ret;
	const Variant *args[1] = { &p_key };
	if (!const_cast<Variant &>(value_).call("has", args, 1, ret)) {
		return false;
	}
	return ret.as_bool();
}

int64_t Dictionary::size() const {
	return size_of(value_);
}

Array Dictionary::keys() const {
	Variant ret;
	if (!const_cast<Variant &>(value_).call("keys", ret)) {
		return Array();
	}
	return Array(std::move(ret));
}

PackedStringArray::PackedStringArray() :
		value_(make_default(VariantType::PACKED_STRING_ARRAY)) {}

void PackedStringArray::append(std::string_view p_text) {
	Variant ret;
	const Variant text{ std::string(p_text) };
	const Variant *args[1] = { &text };
	value_.call("append", args, 1, ret);
}

int64_t PackedStringArray::size() const {
	return size_of(value_);
}

Array::Array() :
		value_(make_default(VariantType::ARRAY)) {}

void Array::append(const Variant &p_value) {
	Variant ret;
	const Variant *args[1] = { &p_value };
	const_cast<Variant &>(value_).call("append", args, 1, ret);
}

int64_t Array::size() const {
	return size_of(value_);
}

Variant Array::get(int64_t p_index) const {
	GDExtensionBool valid = 0;
	GDExtensionBool out_of_bounds = 0;
	Variant value = Variant::from_engine([&](GDExtensionUninitializedVariantPtr r_dst) {
		api.variant_get_indexed(value_.ptr(), p_index, r_dst, &valid, &out_of_bounds);
	});
	if (!valid || out_of_bounds) {
		return Variant();
	}
	return value;
}

template <typename T, VariantType TYPE>
PackedArray<T, TYPE>::PackedArray() :
		value_(make_default(TYPE)) {}

template <typename T, VariantType TYPE>
int64_t PackedArray<T, TYPE>::size() const {
	return size_of(value_);
}

template <typename T, VariantType TYPE>
bool PackedArray<T, TYPE>::resize(int64_t p_size) {
	Variant ret;
	Variant size(p_size);
	const Variant *args[1] = { &size };
	// Called on our own Variant, so the resize happens in place, not on a copy.
	return value_.call("resize", args, 1, ret) && ret.as_int() == 0;
}

namespace {

void *internal(const Variant &p_value, VariantType p_type) {
	return api.variant_get_ptr_internal_getter(static_cast<GDExtensionVariantType>(p_type))(
			const_cast<GDExtensionVariantPtr>(p_value.ptr()));
}

} // namespace

template <>
uint8_t *PackedByteArray::ptrw() {
	if (size() == 0) {
		return nullptr;
	}
	return api.packed_byte_array_operator_index(internal(value_, VariantType::PACKED_BYTE_ARRAY), 0);
}

template <>
const uint8_t *PackedByteArray::ptr() const {
	if (size() == 0) {
		return nullptr;
	}
	return api.packed_byte_array_operator_index_const(internal(value_, VariantType::PACKED_BYTE_ARRAY), 0);
}

template <>
float *PackedFloat32Array::ptrw() {
	if (size() == 0) {
		return nullptr;
	}
	return api.packed_float32_array_operator_index(internal(value_, VariantType::PACKED_FLOAT32_ARRAY),
			0);
}

template <>
const float *PackedFloat32Array::ptr() const {
	if (size() == 0) {
		return nullptr;
	}
	return api.packed_float32_array_operator_index_const(
			internal(value_, VariantType::PACKED_FLOAT32_ARRAY), 0);
}

template <>
Vector2 *PackedVector2Array::ptrw() {
	if (size() == 0) {
		return nullptr;
	}
	return reinterpret_cast<Vector2 *>(api.packed_vector2_array_operator_index(
			internal(value_, VariantType::PACKED_VECTOR2_ARRAY), 0));
}

template <>
const Vector2 *PackedVector2Array::ptr() const {
	if (size() == 0) {
		return nullptr;
	}
	return reinterpret_cast<const Vector2 *>(api.packed_vector2_array_operator_index_const(
			internal(value_, VariantType::PACKED_VECTOR2_ARRAY), 0));
}

template class PackedArray<uint8_t, VariantType::PACKED_BYTE_ARRAY>;
template class PackedArray<float, VariantType::PACKED_FLOAT32_ARRAY>;
template class PackedArray<Vector2, VariantType::PACKED_VECTOR2_ARRAY>;

} // namespace gd
