// Where the GLSL sources live: $ISPM_SHADER_DIR, else the source tree the binary was built from.
#pragma once

#include <filesystem>

namespace ispm {

std::filesystem::path getShaderRoot();

} // namespace ispm
