#pragma once

// The movement renderer's settings (MovementConfig: its contact law, ForceModelConfig, and
// its output filter, SmoothingConfig) and ContactModel are defined in movement.schema.toml:
// each field's range, unit and why it has its default. force_model.h has the equations of
// both contact models.

#include "core/render/frame.h"
#include "renderers/movement/movement.gen.h"
