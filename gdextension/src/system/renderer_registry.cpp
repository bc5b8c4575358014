#include "system/renderer_registry.h"

#include "system/renderer_table.h"

namespace haptics {

std::span<const RegisteredRenderer> registered_renderers() {
#define HAPTICS_ROW_OF(MODE, name, Class) { #name, &Class::info() },
	static const RegisteredRenderer ROWS[] = { HAPTICS_RENDERERS(HAPTICS_ROW_OF) };
#undef HAPTICS_ROW_OF
	return ROWS;
}

} // namespace haptics
