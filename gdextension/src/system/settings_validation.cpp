#include "system/settings_validation.h"

#include "core/wire/codec.h"

namespace haptics {

namespace {

// Status::success() for a renderer without joint limits.
template <typename R>
Status validate_settings(const typename R::Config &p_config) {
	HAPTICS_RETURN_IF_ERROR(check_fields(p_config));
	if constexpr (requires { R::validate(p_config); }) {
		return R::validate(p_config);
	} else {
		return Status::success();
	}
}

} // namespace

Status validate_render_config(const RenderConfig &p_config) {
	HAPTICS_RETURN_IF_ERROR(check_fields(static_cast<const ServoSettings &>(p_config.servo)));
#define HAPTICS_VALIDATE_OF(MODE, name, Class) HAPTICS_RETURN_IF_ERROR(validate_settings<Class>(p_config.name));
	HAPTICS_RENDERERS(HAPTICS_VALIDATE_OF)
#undef HAPTICS_VALIDATE_OF
	const int32_t mode = p_config.servo.render_mode;
	if (mode < 0 || static_cast<size_t>(mode) >= RENDER_MODE_COUNT) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "render_mode: unknown mode %d", static_cast<int>(mode));
	}
	return Status::success();
}

} // namespace haptics
