// The library's entry point: resolves the engine interface and registers our classes at
// the scene level (they use scene-level types such as Dictionary only through Variants,
// but their users live in scenes); in the editor, loads their class reference. A
// development build (HAPTICS_DEV_TOOLS) also adds its software device models to the
// device factory, here and nowhere else.
#include "binding/class_db.h"
#include "binding/doc_data.h"
#include "binding/durable_file_binding.h"
#include "binding/interface.h"
#include "binding/system_object.h"

#if HAPTICS_DEV_TOOLS
#include "dev_tools/scripted_backends.h"
#endif

// The one symbol the library exports (everything else is hidden, and on Windows nothing is
// exported unless marked).
#ifdef _WIN32
#define HAPTICS_EXPORT __declspec(dllexport)
#else
#define HAPTICS_EXPORT __attribute__((visibility("default")))
#endif

namespace {

void initialize(void * /*p_userdata*/, GDExtensionInitializationLevel p_level) {
	if (p_level == GDEXTENSION_INITIALIZATION_EDITOR) {
		haptics::binding::load_editor_help();
	}
	if (p_level != GDEXTENSION_INITIALIZATION_SCENE) {
		return;
	}
#if HAPTICS_DEV_TOOLS
	haptics::register_scripted_devices();
#endif
	gd::register_class<haptics::binding::SystemObject>("HapticsSystem", "RefCounted");
	gd::register_class<haptics::binding::DurableFile>("DurableFile", "RefCounted");
}

void deinitialize(void * /*p_userdata*/, GDExtensionInitializationLevel p_level) {
	if (p_level != GDEXTENSION_INITIALIZATION_SCENE) {
		return;
	}
	gd::unregister_classes();
}

} // namespace

extern "C" {

HAPTICS_EXPORT GDExtensionBool haptics_library_init(
		GDExtensionInterfaceGetProcAddress p_get_proc_address, GDExtensionClassLibraryPtr p_library,
		GDExtensionInitialization *r_initialization) {
	if (!gd::load_interface(p_get_proc_address, p_library)) {
		return 0;
	}
	r_initialization->minimum_initialization_level = GDEXTENSION_INITIALIZATION_SCENE;
	r_initialization->userdata = nullptr;
	r_initialization->initialize = &initialize;
	r_initialization->deinitialize = &deinitialize;
	return 1;
}

} // extern "C"
