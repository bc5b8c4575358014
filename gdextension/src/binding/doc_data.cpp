#include "binding/doc_data.h"

#include <cstring>

#include "binding/interface.h"

namespace haptics::binding {

void load_editor_help() {
	const auto load = reinterpret_cast<GDExtensionsInterfaceEditorHelpLoadXmlFromUtf8CharsAndLen>(
			gd::api.get_proc_address("editor_help_load_xml_from_utf8_chars_and_len"));
	if (load == nullptr) {
		return;
	}
	for (size_t i = 0; i < DOC_CLASS_COUNT; ++i) {
		load(DOC_CLASSES[i], static_cast<GDExtensionInt>(std::strlen(DOC_CLASSES[i])));
	}
}

} // namespace haptics::binding
