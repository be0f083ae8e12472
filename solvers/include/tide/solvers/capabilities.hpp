#pragma once

// What the schemes support: the one place that refuses a scene whose settings are each valid but
// whose combination no scheme runs (several fluid materials with continuity density, surface
// tension with an incompressible scheme, ...). `tide check` and `tide run` call it after reading a
// scene, and the schemes' constructors before building anything.

#include "tide/core/scene.hpp"

namespace tide {

/// Throws a scene::SceneError naming the scene's source, the key path of the setting to change
/// and what is supported instead.
void check_capabilities(const scene::Scene& scene);

}  // namespace tide
