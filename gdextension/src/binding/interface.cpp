#include "binding/interface.h"

#include <cstdio>

namespace gd {

Interface api;

namespace {

template <typename T>
bool resolve(GDExtensionInterfaceGetProcAddress p_get, const char *p_name, T &r_fn) {
	r_fn = reinterpret_cast<T>(p_get(p_name));
	if (r_fn == nullptr) {
		// The engine's own error printer may be the very thing missing, so stderr it is.
		std::fprintf(stderr, "haptics: the engine does not provide '%s' (needs Godot 4.5+)\n",
				p_name);
		return false;
	}
	return true;
}

} // namespace

bool load_interface(GDExtensionInterfaceGetProcAddress p_get, GDExtensionClassLibraryPtr p_library) {
	api.library = p_library;
	api.get_proc_address = p_get;
	bool ok = true;
#define HAPTICS_RESOLVE(name) ok = resolve(p_get, #name, api.name) && ok
	HAPTICS_RESOLVE(get_godot_version2);
	HAPTICS_RESOLVE(print_error_with_message);
	HAPTICS_RESOLVE(print_warning_with_message);
	HAPTICS_RESOLVE(variant_new_copy);
	HAPTICS_RESOLVE(variant_new_nil);
	HAPTICS_RESOLVE(variant_destroy);
	HAPTICS_RESOLVE(variant_call);
	HAPTICS_RESOLVE(variant_set);
	HAPTICS_RESOLVE(variant_get);
	HAPTICS_RESOLVE(variant_get_indexed);
	HAPTICS_RESOLVE(variant_get_type);
	HAPTICS_RESOLVE(variant_can_convert_strict);
	HAPTICS_RESOLVE(variant_construct);
	HAPTICS_RESOLVE(variant_stringify);
	HAPTICS_RESOLVE(get_variant_from_type_constructor);
	HAPTICS_RESOLVE(get_variant_to_type_constructor);
	HAPTICS_RESOLVE(variant_get_ptr_internal_getter);
	HAPTICS_RESOLVE(variant_get_ptr_destructor);
	HAPTICS_RESOLVE(variant_get_ptr_constructor);
	HAPTICS_RESOLVE(string_new_with_utf8_chars_and_len2);
	HAPTICS_RESOLVE(string_to_utf8_chars);
	HAPTICS_RESOLVE(string_name_new_with_utf8_chars_and_len);
	HAPTICS_RESOLVE(packed_byte_array_operator_index);
	HAPTICS_RESOLVE(packed_byte_array_operator_index_const);
	HAPTICS_RESOLVE(packed_float32_array_operator_index);
	HAPTICS_RESOLVE(packed_vector2_array_operator_index);
	HAPTICS_RESOLVE(packed_float32_array_operator_index_const);
	HAPTICS_RESOLVE(packed_vector2_array_operator_index_const);
	HAPTICS_RESOLVE(classdb_construct_object2);
	HAPTICS_RESOLVE(object_set_instance);
	HAPTICS_RESOLVE(classdb_register_extension_class5);
	HAPTICS_RESOLVE(classdb_register_extension_class_method);
	HAPTICS_RESOLVE(classdb_register_extension_class_integer_constant);
	HAPTICS_RESOLVE(classdb_unregister_extension_class);
#undef HAPTICS_RESOLVE
	if (!ok) {
		return false;
	}
	GDExtensionGodotVersion2 version{};
	api.get_godot_version2(&version);
	api.version_major = version.major;
	api.version_minor = version.minor;
	api.version_patch = version.patch;
	return true;
}

} // namespace gd
