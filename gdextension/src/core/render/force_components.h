#pragma once

// The force of one servo tick, piece by piece, for the HUD and telemetry (forces.schema.toml:
// ForceComponents, HapticForces in GDScript). The active renderer fills its own components
// (`parts`, in the order of its force enum: RendererInfo::force_names) and their sum; the
// servo pipeline fills the rest. Device space.

#include "core/render/forces.gen.h"
