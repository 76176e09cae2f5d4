// Scene files (JSON, docs/scene-format.md) to the scene model. Every mistake in a file becomes an
// InputError "<file>: <JSON path>: expected <what>" on one line; nothing is silently defaulted.
#pragma once

#include "scene/obj_io.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace ispm {

// Reads and parses the file; `path` as given is the file name in messages, and relative paths
// inside the scene (OBJ files) are taken from the file's directory.
Scene loadScene(const std::string& path);

// Parses a document already read. `file` names it in messages; `baseDir` resolves relative paths.
Scene parseScene(const nlohmann::json& doc, const std::string& file, const std::string& baseDir);

} // namespace ispm
