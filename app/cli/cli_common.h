// Pieces the subcommands share: output kinds, effective settings, read-back, timing tables.
#pragma once

#include "gl/context.h"
#include "render/frame.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace ispm {

// --camera NAME on a subcommand that loads a scene (one of the file's `cameras`).
void addCameraOption(CLI::App& cmd, std::string& cameraName);

enum class OutputKind { Png, Pfm, Exr };

// From the file extension; throws InputError naming `where` for anything else.
OutputKind classifyOutput(const std::string& path, const std::string& where);
// Throws InputError naming `where` when `path` cannot be written: its folder missing or not
// writable, or a folder in its place. Checked before a render, not after it.
void checkWritableOutput(const std::string& path, const std::string& where);

// --set values, then --width/--height, checked against the settings table. Callers merge the
// result over the scene's `render` block (the command line wins).
Settings makeCommandLineSettings(const std::vector<std::string>& sets, std::optional<int> width,
                                 std::optional<int> height);

void printTimings(const FrameRunner& runner, const gl::ContextInfo& info);

// "ispm: warning: ..." on stderr when the settings make light vanish (describeOversizedSplats).
void warnIfLightFades(const FrameRunner& runner);

// The exit code of a command that rendered: 1 (with a line naming `while`) when KHR_debug
// reported OpenGL errors during the run, else 0.
int checkGlErrors(const char* whileDoing);

} // namespace ispm
