// The class reference (gdextension/doc_classes/*.xml), embedded at build time so the editor
// shows it under Help for HapticsSystem and DurableFile.
#pragma once

#include <cstddef>

namespace haptics::binding {

extern const char *const DOC_CLASSES[];
extern const size_t DOC_CLASS_COUNT;

// Hands DOC_CLASSES to the editor's help; does nothing where there is no editor (export
// templates do not provide the function).
void load_editor_help();

} // namespace haptics::binding
