// The engine's C interface, resolved once at load time. This is the only header that
// includes gdextension_interface.h; everything else in src/binding/ goes through the typed
// wrappers built on it, and nothing outside src/binding/ sees either.
#pragma once

#include <gdextension_interface.h>

namespace gd {

// One pointer per interface function we use, named after the engine's own names.
struct Interface {
	GDExtensionClassLibraryPtr library = nullptr;
	// For functions only some builds have (the editor's help), looked up when needed.
	GDExtensionInterfaceGetProcAddress get_proc_address = nullptr;
	uint32_t version_major = 0;
	uint32_t version_minor = 0;
	uint32_t version_patch = 0;

	GDExtensionInterfaceGetGodotVersion2 get_godot_version2 = nullptr;
	GDExtensionInterfacePrintErrorWithMessage print_error_with_message = nullptr;
	GDExtensionInterfacePrintWarningWithMessage print_warning_with_message = nullptr;

	GDExtensionInterfaceVariantNewCopy variant_new_copy = nullptr;
	GDExtensionInterfaceVariantNewNil variant_new_nil = nullptr;
	GDExtensionInterfaceVariantDestroy variant_destroy = nullptr;
	GDExtensionInterfaceVariantCall variant_call = nullptr;
	GDExtensionInterfaceVariantSet variant_set = nullptr;
	GDExtensionInterfaceVariantGet variant_get = nullptr;
	GDExtensionInterfaceVariantGetIndexed variant_get_indexed = nullptr;
	GDExtensionInterfaceVariantGetType variant_get_type = nullptr;
	GDExtensionInterfaceVariantCanConvertStrict variant_can_convert_strict = nullptr;
	GDExtensionInterfaceVariantConstruct variant_construct = nullptr;
	GDExtensionInterfaceVariantStringify variant_stringify = nullptr;
	GDExtensionInterfaceGetVariantFromTypeConstructor get_variant_from_type_constructor = nullptr;
	GDExtensionInterfaceGetVariantToTypeConstructor get_variant_to_type_constructor = nullptr;
	GDExtensionInterfaceGetVariantGetInternalPtrFunc variant_get_ptr_internal_getter = nullptr;
	GDExtensionInterfaceVariantGetPtrDestructor variant_get_ptr_destructor = nullptr;
	GDExtensionInterfaceVariantGetPtrConstructor variant_get_ptr_constructor = nullptr;

	GDExtensionInterfaceStringNewWithUtf8CharsAndLen2 string_new_with_utf8_chars_and_len2 = nullptr;
	GDExtensionInterfaceStringToUtf8Chars string_to_utf8_chars = nullptr;
	GDExtensionInterfaceStringNameNewWithUtf8CharsAndLen string_name_new_with_utf8_chars_and_len =
			nullptr;
	GDExtensionInterfacePackedByteArrayOperatorIndex packed_byte_array_operator_index = nullptr;
	GDExtensionInterfacePackedFloat32ArrayOperatorIndex packed_float32_array_operator_index = nullptr;
	GDExtensionInterfacePackedVector2ArrayOperatorIndex packed_vector2_array_operator_index = nullptr;
	GDExtensionInterfacePackedByteArrayOperatorIndexConst packed_byte_array_operator_index_const = nullptr;
	GDExtensionInterfacePackedFloat32ArrayOperatorIndexConst
			packed_float32_array_operator_index_const = nullptr;
	GDExtensionInterfacePackedVector2ArrayOperatorIndexConst
			packed_vector2_array_operator_index_const = nullptr;

	GDExtensionInterfaceClassdbConstructObject2 classdb_construct_object2 = nullptr;
	GDExtensionInterfaceObjectSetInstance object_set_instance = nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClass5 classdb_register_extension_class5 = nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClassMethod classdb_register_extension_class_method =
			nullptr;
	GDExtensionInterfaceClassdbRegisterExtensionClassIntegerConstant
			classdb_register_extension_class_integer_constant = nullptr;
	GDExtensionInterfaceClassdbUnregisterExtensionClass classdb_unregister_extension_class = nullptr;
};

// Filled by load_interface(); read-only afterwards.
extern Interface api;

// Resolves every pointer above. Returns false (and prints why, if it can) when the engine
// lacks one of them, i.e. is older than the 4.5 interface we compile against.
bool load_interface(GDExtensionInterfaceGetProcAddress p_get_proc_address,
		GDExtensionClassLibraryPtr p_library);

} // namespace gd
