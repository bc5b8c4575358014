#pragma once

// The constraint renderer's settings (ConstraintConfig) and ProxyUpdate are defined in
// constraint.schema.toml: each field's range, unit and why it has its default.

#include "renderers/constraint/constraint.gen.h"
