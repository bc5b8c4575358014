// Owning C++ wrappers over the engine's Variant, String and StringName, plus the plain
// math types. Names follow godot-cpp so that the binding could later move onto it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "binding/interface.h"

namespace gd {

enum class VariantType : int {
	NIL = GDEXTENSION_VARIANT_TYPE_NIL,
	BOOL = GDEXTENSION_VARIANT_TYPE_BOOL,
	INT = GDEXTENSION_VARIANT_TYPE_INT,
	FLOAT = GDEXTENSION_VARIANT_TYPE_FLOAT,
	STRING = GDEXTENSION_VARIANT_TYPE_STRING,
	VECTOR2 = GDEXTENSION_VARIANT_TYPE_VECTOR2,
	VECTOR3 = GDEXTENSION_VARIANT_TYPE_VECTOR3,
	STRING_NAME = GDEXTENSION_VARIANT_TYPE_STRING_NAME,
	DICTIONARY = GDEXTENSION_VARIANT_TYPE_DICTIONARY,
	ARRAY = GDEXTENSION_VARIANT_TYPE_ARRAY,
	PACKED_BYTE_ARRAY = GDEXTENSION_VARIANT_TYPE_PACKED_BYTE_ARRAY,
	PACKED_FLOAT32_ARRAY = GDEXTENSION_VARIANT_TYPE_PACKED_FLOAT32_ARRAY,
	PACKED_STRING_ARRAY = GDEXTENSION_VARIANT_TYPE_PACKED_STRING_ARRAY,
	PACKED_VECTOR2_ARRAY = GDEXTENSION_VARIANT_TYPE_PACKED_VECTOR2_ARRAY,
};

// Same layout as the engine's single-precision Vector2/Vector3, so ptrcall slots can be
// read and written directly.
struct Vector2 {
	float x = 0.0f;
	float y = 0.0f;
};
struct Vector3 {
	float x = 0.0f;
	float y = 0.0f;
	float z = 0.0f;
};
static_assert(sizeof(Vector2) == 8 && sizeof(Vector3) == 12);

// Engine StringName. Needed for every name handed to ClassDB.
class StringName {
public:
	explicit StringName(std::string_view p_utf8);
	StringName(const StringName &) = delete;
	StringName &operator=(const StringName &) = delete;
	~StringName();
	GDExtensionConstStringNamePtr ptr() const { return opaque_; }
	GDExtensionStringNamePtr ptr() { return opaque_; }

private:
	alignas(8) uint8_t opaque_[8] = {};
};

// Engine String, converted from and to UTF-8.
class String {
public:
	String();
	explicit String(std::string_view p_utf8);
	String(const String &) = delete;
	String &operator=(const String &) = delete;
	~String();
	GDExtensionStringPtr ptr() { return opaque_; }
	GDExtensionConstStringPtr ptr() const { return opaque_; }
	std::string utf8() const;

private:
	alignas(8) uint8_t opaque_[8] = {};
};

// Engine Variant, owned: copied with the engine's copy, destroyed with its destructor.
class Variant {
public:
	Variant();
	Variant(bool p_value);
	Variant(int64_t p_value);
	Variant(int p_value) :
			Variant(static_cast<int64_t>(p_value)) {}
	Variant(double p_value);
	Variant(std::string_view p_utf8);
	Variant(const char *p_utf8) :
			Variant(std::string_view(p_utf8)) {}
	Variant(const std::string &p_utf8) :
			Variant(std::string_view(p_utf8)) {}
	Variant(Vector2 p_value);
	Variant(Vector3 p_value);
	Variant(const Variant &p_other);
	Variant(Variant &&p_other) noexcept;
	Variant &operator=(const Variant &p_other);
	Variant &operator=(Variant &&p_other) noexcept;
	~Variant();

	// Adopts a value the engine wrote into uninitialised Variant storage.
	template <typename F>
	static Variant from_engine(F &&p_fill) {
		Variant v(Uninitialized{});
		p_fill(v.ptr());
		return v;
	}
	// Builds a Variant from a pointer to a native value of type p_type (ptrcall slots).
	static Variant from_native(VariantType p_type, const void *p_native);
	// Writes this Variant, converted to p_type, over the already constructed native value at
	// r_native (a ptrcall return slot). The Variant must already hold p_type.
	void to_native(VariantType p_type, void *r_native) const;

	VariantType get_type() const;
	bool is_nil() const { return get_type() == VariantType::NIL; }
	// Converts to p_type the way the engine does for method arguments; false if it cannot.
	bool convert_strict(VariantType p_type, Variant &r_out) const;

	bool as_bool() const;
	int64_t as_int() const;
	double as_float() const;
	std::string as_string() const; // String or StringName; others are stringified.
	Vector2 as_vector2() const;
	Vector3 as_vector3() const;
	// The engine's text form of any value (for error messages).
	std::string stringify() const;

	// Calls a builtin method by name (Dictionary.size, Array.append…); false on error.
	bool call(const char *p_method, const Variant *const *p_args, int p_count, Variant &r_ret);
	bool call(const char *p_method, Variant &r_ret) { return call(p_method, nullptr, 0, r_ret); }

	GDExtensionVariantPtr ptr() { return opaque_; }
	GDExtensionConstVariantPtr ptr() const { return opaque_; }

private:
	struct Uninitialized {};
	explicit Variant(Uninitialized) {}
	alignas(8) uint8_t opaque_[24] = {};
};

} // namespace gd
