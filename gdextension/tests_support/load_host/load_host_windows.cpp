// A minimal GDExtension host for Windows (run under Wine by tools/windows/test.sh): loads the
// extension DLL with LoadLibrary, calls its entry point with a get_proc_address that serves
// recording stand-ins for what the library uses at initialisation, runs every initialisation
// level and deinitialisation as the engine does, and prints what the library registered:
//   class <name> <parent> methods=<n> constants=<n>
//   docs <n> (malformed <n>)
//   unregistered <n>
// Exit 0 only when the entry point returned true and both classes registered with methods;
// 2 when the DLL or its entry point cannot be found. It shows the DLL loads on Windows'
// loader, binds its imports and runs its registration code; the engine's real functions are
// not here, so nothing is called on an instance.
#include <gdextension_interface.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <windows.h>

namespace {

constexpr const char *ENTRY_SYMBOL = "haptics_library_init";
constexpr const char *EXPECTED_CLASSES[] = { "HapticsSystem", "DurableFile" };

struct RegisteredClass {
	std::string parent;
	int methods = 0;
	int constants = 0;
};

// A StringName is an opaque pointer-sized value to the library: ours is an index into names.
std::vector<std::string> names;
std::map<std::string, RegisteredClass> classes;
int unregistered = 0;
int unknown_calls = 0;

std::string name_of(GDExtensionConstStringNamePtr p_name) {
	size_t index = 0;
	std::memcpy(&index, p_name, sizeof(index));
	return index < names.size() ? names[index] : std::string("?");
}

void string_name_new(GDExtensionUninitializedStringNamePtr r_dest, const char *p_contents, GDExtensionInt p_size) {
	const size_t index = names.size();
	names.emplace_back(p_contents, p_size < 0 ? std::strlen(p_contents) : static_cast<size_t>(p_size));
	std::memcpy(r_dest, &index, sizeof(index));
}

void godot_version(GDExtensionGodotVersion2 *r_version) {
	*r_version = GDExtensionGodotVersion2{};
	r_version->major = 4;
	r_version->minor = 6;
	r_version->string = "load_host";
}

void register_class(GDExtensionClassLibraryPtr, GDExtensionConstStringNamePtr p_name,
		GDExtensionConstStringNamePtr p_parent, const GDExtensionClassCreationInfo5 *) {
	classes[name_of(p_name)].parent = name_of(p_parent);
}

void register_method(GDExtensionClassLibraryPtr, GDExtensionConstStringNamePtr p_class,
		const GDExtensionClassMethodInfo *) {
	++classes[name_of(p_class)].methods;
}

void register_constant(GDExtensionClassLibraryPtr, GDExtensionConstStringNamePtr p_class,
		GDExtensionConstStringNamePtr, GDExtensionConstStringNamePtr, GDExtensionInt, GDExtensionBool) {
	++classes[name_of(p_class)].constants;
}

void unregister_class(GDExtensionClassLibraryPtr, GDExtensionConstStringNamePtr) {
	++unregistered;
}

// The class reference the editor shows: each document must name a class.
int docs_loaded = 0;
int docs_malformed = 0;
void load_docs(const char *p_data, GDExtensionInt p_size) {
	const std::string xml(p_data, static_cast<size_t>(p_size));
	++(xml.find("<class name=\"") != std::string::npos ? docs_loaded : docs_malformed);
}

// Default arguments are Variants: copied and destroyed as opaque values here.
constexpr size_t VARIANT_BYTES = 24;
void variant_copy(GDExtensionUninitializedVariantPtr r_dest, GDExtensionConstVariantPtr p_source) {
	std::memcpy(r_dest, p_source, VARIANT_BYTES);
}
void variant_destroy(GDExtensionVariantPtr) {}

void no_op_destructor(GDExtensionTypePtr) {}
void no_op_constructor(GDExtensionUninitializedTypePtr, const GDExtensionConstTypePtr *) {}
void no_op_conversion(void *, void *) {}
GDExtensionPtrDestructor get_destructor(GDExtensionVariantType) {
	return no_op_destructor;
}
GDExtensionPtrConstructor get_constructor(GDExtensionVariantType, int32_t) {
	return no_op_constructor;
}
GDExtensionVariantFromTypeConstructorFunc get_from_type(GDExtensionVariantType) {
	return no_op_conversion;
}
GDExtensionTypeFromVariantConstructorFunc get_to_type(GDExtensionVariantType) {
	return no_op_conversion;
}
// Anything else the library resolves: it must exist (a null would fail its load), and is
// counted by name if called during registration (where the engine's real one would have been).
constexpr int UNKNOWN_SLOTS = 256;
std::vector<std::string> unknown_names;
std::map<std::string, int> unknown_called;

template <int I>
void unknown_function() {
	++unknown_calls;
	++unknown_called[static_cast<size_t>(I) < unknown_names.size() ? unknown_names[I] : std::string("?")];
}

template <int... I>
constexpr auto make_unknown_table(std::integer_sequence<int, I...>) {
	return std::array<void (*)(), sizeof...(I)>{ &unknown_function<I>... };
}
constexpr auto UNKNOWN_TABLE = make_unknown_table(std::make_integer_sequence<int, UNKNOWN_SLOTS>{});

template <typename F>
GDExtensionInterfaceFunctionPtr as_function(F p_function) {
	return reinterpret_cast<GDExtensionInterfaceFunctionPtr>(p_function);
}

struct Served {
	const char *name;
	GDExtensionInterfaceFunctionPtr function;
};

const Served SERVED[] = {
	{ "get_godot_version2", as_function(godot_version) },
	{ "string_name_new_with_utf8_chars_and_len", as_function(string_name_new) },
	{ "classdb_register_extension_class5", as_function(register_class) },
	{ "classdb_register_extension_class_method", as_function(register_method) },
	{ "classdb_register_extension_class_integer_constant", as_function(register_constant) },
	{ "classdb_unregister_extension_class", as_function(unregister_class) },
	{ "editor_help_load_xml_from_utf8_chars_and_len", as_function(load_docs) },
	{ "variant_new_copy", as_function(variant_copy) },
	{ "variant_destroy", as_function(variant_destroy) },
	{ "variant_get_ptr_destructor", as_function(get_destructor) },
	{ "variant_get_ptr_constructor", as_function(get_constructor) },
	{ "get_variant_from_type_constructor", as_function(get_from_type) },
	{ "get_variant_to_type_constructor", as_function(get_to_type) },
};

GDExtensionInterfaceFunctionPtr get_proc_address(const char *p_name) {
	for (const Served &served : SERVED) {
		if (std::strcmp(served.name, p_name) == 0) {
			return served.function;
		}
	}
	const size_t slot = unknown_names.size() < UNKNOWN_SLOTS ? unknown_names.size() : UNKNOWN_SLOTS - 1;
	if (unknown_names.size() < UNKNOWN_SLOTS) {
		unknown_names.emplace_back(p_name);
	}
	return as_function(UNKNOWN_TABLE[slot]);
}

} // namespace

int main(int p_argc, char **p_argv) {
	if (p_argc != 2) {
		std::fprintf(stderr, "usage: load_host LIBRARY.dll\n");
		return 2;
	}
	HMODULE library = LoadLibraryA(p_argv[1]);
	if (library == nullptr) {
		std::fprintf(stderr, "load_host: LoadLibrary(%s) failed: Windows error %lu\n", p_argv[1], GetLastError());
		return 2;
	}
	using Entry = GDExtensionBool (*)(GDExtensionInterfaceGetProcAddress, GDExtensionClassLibraryPtr,
			GDExtensionInitialization *);
	const auto entry = reinterpret_cast<Entry>(reinterpret_cast<void (*)()>(GetProcAddress(library, ENTRY_SYMBOL)));
	if (entry == nullptr) {
		std::fprintf(stderr, "load_host: %s does not export %s\n", p_argv[1], ENTRY_SYMBOL);
		return 2;
	}
	static int library_token = 0;
	GDExtensionInitialization initialization{};
	if (!entry(get_proc_address, &library_token, &initialization)) {
		std::fprintf(stderr, "load_host: %s returned false\n", ENTRY_SYMBOL);
		return 1;
	}
	std::printf("entry point: minimum level %d\n", static_cast<int>(initialization.minimum_initialization_level));
	for (int level = initialization.minimum_initialization_level; level < GDEXTENSION_MAX_INITIALIZATION_LEVEL;
			++level) {
		initialization.initialize(initialization.userdata, static_cast<GDExtensionInitializationLevel>(level));
	}
	for (const auto &[name, registered] : classes) {
		std::printf("class %s %s methods=%d constants=%d\n", name.c_str(), registered.parent.c_str(),
				registered.methods, registered.constants);
	}
	for (int level = GDEXTENSION_MAX_INITIALIZATION_LEVEL - 1; level >= initialization.minimum_initialization_level;
			--level) {
		initialization.deinitialize(initialization.userdata, static_cast<GDExtensionInitializationLevel>(level));
	}
	std::printf("docs %d (malformed %d)\nunregistered %d\nunknown calls %d\n", docs_loaded, docs_malformed,
			unregistered, unknown_calls);
	for (const auto &[name, count] : unknown_called) {
		std::printf("  %s x%d\n", name.c_str(), count);
	}
	bool ok = unregistered == static_cast<int>(classes.size()) && unknown_calls == 0 && docs_malformed == 0;
	for (const char *expected : EXPECTED_CLASSES) {
		const auto found = classes.find(expected);
		ok = ok && found != classes.end() && found->second.methods > 0 && found->second.parent == "RefCounted";
	}
	FreeLibrary(library);
	std::printf("%s\n", ok ? "load_host: ok" : "load_host: FAILED");
	return ok ? 0 : 1;
}
