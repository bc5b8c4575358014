#include "binding/variant.h"

#include <cstring>
#include <utility>

namespace gd {

namespace {

GDExtensionVariantType raw(VariantType p_type) {
	return static_cast<GDExtensionVariantType>(p_type);
}

// Engine functions take non-const pointers even where they only read.
GDExtensionTypePtr unconst(const void *p_ptr) {
	return const_cast<void *>(p_ptr);
}

template <typename T>
Variant variant_from(VariantType p_type, const T &p_value) {
	return Variant::from_engine([&](GDExtensionUninitializedVariantPtr r_dst) {
		api.get_variant_from_type_constructor(raw(p_type))(r_dst, unconst(&p_value));
	});
}

template <typename T>
T variant_to(VariantType p_type, const Variant &p_value) {
	T out{};
	api.get_variant_to_type_constructor(raw(p_type))(&out,
			const_cast<GDExtensionVariantPtr>(p_value.ptr()));
	return out;
}

} // namespace

StringName::StringName(std::string_view p_utf8) {
	api.string_name_new_with_utf8_chars_and_len(opaque_, p_utf8.data(),
			static_cast<GDExtensionInt>(p_utf8.size()));
}

StringName::~StringName() {
	api.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_STRING_NAME)(opaque_);
}

String::String() {
	api.variant_get_ptr_constructor(GDEXTENSION_VARIANT_TYPE_STRING, 0)(opaque_, nullptr);
}

String::String(std::string_view p_utf8) {
	api.string_new_with_utf8_chars_and_len2(opaque_, p_utf8.data(),
			static_cast<GDExtensionInt>(p_utf8.size()));
}

String::~String() {
	api.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_STRING)(opaque_);
}

std::string String::utf8() const {
	const GDExtensionInt length = api.string_to_utf8_chars(opaque_, nullptr, 0);
	std::string out(static_cast<size_t>(length), '\0');
	api.string_to_utf8_chars(opaque_, out.data(), length);
	return out;
}

Variant::Variant() {
	api.variant_new_nil(opaque_);
}

Variant::Variant(bool p_value) {
	const GDExtensionBool value = p_value ? 1 : 0;
	*this = variant_from(VariantType::BOOL, value);
}

Variant::Variant(int64_t p_value) {
	*this = variant_from(VariantType::INT, p_value);
}

Variant::Variant(double p_value) {
	*this = variant_from(VariantType::FLOAT, p_value);
}

Variant::Variant(std::string_view p_utf8) {
	String s(p_utf8);
	api.get_variant_from_type_constructor(GDEXTENSION_VARIANT_TYPE_STRING)(opaque_, s.ptr());
}

Variant::Variant(Vector2 p_value) {
	*this = variant_from(VariantType::VECTOR2, p_value);
}

Variant::Variant(Vector3 p_value) {
	*this = variant_from(VariantType::VECTOR3, p_value);
}

Variant::Variant(const Variant &p_other) {
	api.variant_new_copy(opaque_, p_other.opaque_);
}

Variant::Variant(Variant &&p_other) noexcept {
	// A Variant's bytes are relocatable; the moved-from object becomes nil without a call.
	std::memcpy(opaque_, p_other.opaque_, sizeof(opaque_));
	std::memset(p_other.opaque_, 0, sizeof(opaque_));
}

Variant &Variant::operator=(const Variant &p_other) {
	if (this != &p_other) {
		api.variant_destroy(opaque_);
		api.variant_new_copy(opaque_, p_other.opaque_);
	}
	return *this;
}

Variant &Variant::operator=(Variant &&p_other) noexcept {
	if (this != &p_other) {
		api.variant_destroy(opaque_);
		std::memcpy(opaque_, p_other.opaque_, sizeof(opaque_));
		std::memset(p_other.opaque_, 0, sizeof(opaque_));
	}
	return *this;
}

Variant::~Variant() {
	// All-zero bytes are a nil Variant (type tag 0), which needs no destruction.
	api.variant_destroy(opaque_);
}

Variant Variant::from_native(VariantType p_type, const void *p_native) {
	return from_engine([&](GDExtensionUninitializedVariantPtr r_dst) {
		api.get_variant_from_type_constructor(raw(p_type))(r_dst, unconst(p_native));
	});
}

void Variant::to_native(VariantType p_type, void *r_native) const {
	api.variant_get_ptr_destructor(raw(p_type))(r_native);
	api.get_variant_to_type_constructor(raw(p_type))(r_native, const_cast<uint8_t *>(opaque_));
}

VariantType Variant::get_type() const {
	return static_cast<VariantType>(api.variant_get_type(opaque_));
}

bool Variant::convert_strict(VariantType p_type, Variant &r_out) const {
	const GDExtensionVariantType from = api.variant_get_type(opaque_);
	if (from == raw(p_type)) {
		r_out = *this;
		return true;
	}
	if (!api.variant_can_convert_strict(from, raw(p_type))) {
		return false;
	}
	GDExtensionCallError error{};
	const GDExtensionConstVariantPtr args[1] = { opaque_ };
	Variant converted(Uninitialized{});
	api.variant_construct(raw(p_type), converted.opaque_, args, 1, &error);
	if (error.error != GDEXTENSION_CALL_OK) {
		return false; // the engine constructed a nil Variant there, destroyed with `converted`
	}
	r_out = std::move(converted);
	return true;
}

bool Variant::as_bool() const {
	return variant_to<GDExtensionBool>(VariantType::BOOL, *this) != 0;
}

int64_t Variant::as_int() const {
	return variant_to<int64_t>(VariantType::INT, *this);
}

double Variant::as_float() const {
	return variant_to<double>(VariantType::FLOAT, *this);
}

std::string Variant::as_string() const {
	if (get_type() != VariantType::STRING && get_type() != VariantType::STRING_NAME) {
		return stringify();
	}
	Variant as_text;
	if (!convert_strict(VariantType::STRING, as_text)) {
		return stringify();
	}
	String s;
	api.variant_get_ptr_destructor(GDEXTENSION_VARIANT_TYPE_STRING)(s.ptr());
	api.get_variant_to_type_constructor(GDEXTENSION_VARIANT_TYPE_STRING)(s.ptr(),
			as_text.ptr());
	return s.utf8();
}

Vector2 Variant::as_vector2() const {
	return variant_to<Vector2>(VariantType::VECTOR2, *this);
}

Vector3 Variant::as_vector3() const {
	return variant_to<Vector3>(VariantType::VECTOR3, *this);
}

std::string Variant::stringify() const {
	String s; // stringify assigns into an already constructed String
	api.variant_stringify(opaque_, s.ptr());
	return s.utf8();
}

bool Variant::call(const char *p_method, const Variant *const *p_args, int p_count,
		Variant &r_ret) {
	StringName method(p_method);
	GDExtensionConstVariantPtr args[8] = {};
	if (p_count > 8) {
		return false;
	}
	for (int i = 0; i < p_count; ++i) {
		args[i] = p_args[i]->ptr();
	}
	GDExtensionCallError error{};
	Variant ret(Uninitialized{});
	api.variant_call(opaque_, method.ptr(), args, p_count, ret.opaque_, &error);
	r_ret = std::move(ret);
	return error.error == GDEXTENSION_CALL_OK;
}

} // namespace gd
