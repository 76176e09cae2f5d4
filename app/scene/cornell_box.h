// The `cornell_box` generator: the measured Cornell box (metres, x 0..0.556, y 0..0.5488,
// z 0..0.5592, opening towards -z) with its white, red and green walls, without the area light.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace ispm {

// Appends one mesh and one instance. Materials are named cornell_white, cornell_red and
// cornell_green; ones the scene already has under those names are used instead.
void addCornellBox(Scene& scene, const glm::mat4& worldFromObject);

} // namespace ispm
