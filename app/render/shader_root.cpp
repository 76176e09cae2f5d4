// Shader root lookup; the environment wins so an installed binary can be pointed at a copy.
#include "render/shader_root.h"

#include <cstdlib>

namespace ispm {

std::filesystem::path getShaderRoot() {
    if (const char* dir = std::getenv("ISPM_SHADER_DIR"); dir && *dir) return dir;
    return ISPM_SHADER_DIR;
}

} // namespace ispm
