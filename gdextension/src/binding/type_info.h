// How each C++ type we expose crosses the boundary: its engine type, and its conversions
// from a Variant (call), from a native slot (ptrcall argument) and back.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>

#include "binding/containers.h"
#include "binding/variant.h"

namespace gd {

template <typename T>
struct TypeInfo;

template <>
struct TypeInfo<bool> {
	static constexpr VariantType type = VariantType::BOOL;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
	static bool from_variant(const Variant &p_v) { return p_v.as_bool(); }
	static bool from_ptr(const void *p_ptr) { return *static_cast<const GDExtensionBool *>(p_ptr) != 0; }
	static Variant to_variant(bool p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, bool p_v) { *static_cast<GDExtensionBool *>(r_ptr) = p_v ? 1 : 0; }
};

template <>
struct TypeInfo<int64_t> {
	static constexpr VariantType type = VariantType::INT;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_INT_IS_INT64;
	static int64_t from_variant(const Variant &p_v) { return p_v.as_int(); }
	static int64_t from_ptr(const void *p_ptr) { return *static_cast<const int64_t *>(p_ptr); }
	static Variant to_variant(int64_t p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, int64_t p_v) { *static_cast<int64_t *>(r_ptr) = p_v; }
};

template <>
struct TypeInfo<double> {
	static constexpr VariantType type = VariantType::FLOAT;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_REAL_IS_DOUBLE;
	static double from_variant(const Variant &p_v) { return p_v.as_float(); }
	// ptrcall passes every float as a double, whatever the build's precision.
	static double from_ptr(const void *p_ptr) { return *static_cast<const double *>(p_ptr); }
	static Variant to_variant(double p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, double p_v) { *static_cast<double *>(r_ptr) = p_v; }
};

template <>
struct TypeInfo<Vector2> {
	static constexpr VariantType type = VariantType::VECTOR2;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
	static Vector2 from_variant(const Variant &p_v) { return p_v.as_vector2(); }
	static Vector2 from_ptr(const void *p_ptr) { return *static_cast<const Vector2 *>(p_ptr); }
	static Variant to_variant(Vector2 p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, Vector2 p_v) { *static_cast<Vector2 *>(r_ptr) = p_v; }
};

// No method takes or returns one yet: Haptic Battle Pong (3D) passes its ball and paddle
// poses as Vector3.
template <>
struct TypeInfo<Vector3> {
	static constexpr VariantType type = VariantType::VECTOR3;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
	static Vector3 from_variant(const Variant &p_v) { return p_v.as_vector3(); }
	static Vector3 from_ptr(const void *p_ptr) { return *static_cast<const Vector3 *>(p_ptr); }
	static Variant to_variant(Vector3 p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, Vector3 p_v) { *static_cast<Vector3 *>(r_ptr) = p_v; }
};

// Types whose native form is engine-managed (refcounted or copy-on-write): both directions
// go through a Variant, which keeps the engine's ownership rules in one place.
template <typename T, VariantType TYPE>
struct ManagedTypeInfo {
	static constexpr VariantType type = TYPE;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
	static T from_variant(const Variant &p_v) { return T(p_v); }
	static T from_ptr(const void *p_ptr) { return from_variant(Variant::from_native(TYPE, p_ptr)); }
	static Variant to_variant(const T &p_v) { return p_v.variant(); }
	static void to_ptr(void *r_ptr, const T &p_v) { to_variant(p_v).to_native(TYPE, r_ptr); }
};

template <>
struct TypeInfo<Dictionary> : ManagedTypeInfo<Dictionary, VariantType::DICTIONARY> {};
template <>
struct TypeInfo<Array> : ManagedTypeInfo<Array, VariantType::ARRAY> {};
template <>
struct TypeInfo<PackedStringArray> : ManagedTypeInfo<PackedStringArray, VariantType::PACKED_STRING_ARRAY> {};
template <>
struct TypeInfo<PackedByteArray> : ManagedTypeInfo<PackedByteArray, VariantType::PACKED_BYTE_ARRAY> {};
template <>
struct TypeInfo<PackedFloat32Array>
		: ManagedTypeInfo<PackedFloat32Array, VariantType::PACKED_FLOAT32_ARRAY> {};
template <>
struct TypeInfo<PackedVector2Array>
		: ManagedTypeInfo<PackedVector2Array, VariantType::PACKED_VECTOR2_ARRAY> {};

// GDScript String <-> UTF-8 std::string.
template <>
struct TypeInfo<std::string> {
	static constexpr VariantType type = VariantType::STRING;
	static constexpr auto metadata = GDEXTENSION_METHOD_ARGUMENT_METADATA_NONE;
	static std::string from_variant(const Variant &p_v) { return p_v.as_string(); }
	static std::string from_ptr(const void *p_ptr) {
		return Variant::from_native(type, p_ptr).as_string();
	}
	static Variant to_variant(const std::string &p_v) { return Variant(p_v); }
	static void to_ptr(void *r_ptr, const std::string &p_v) { Variant(p_v).to_native(type, r_ptr); }
};

template <typename T>
using BareType = std::remove_cvref_t<T>;

} // namespace gd
