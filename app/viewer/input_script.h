// Scripted viewer input (`ispm view --script FILE`): one command a line, replayed frame by frame
// through the same paths as the keyboard, mouse and panels, so tests drive the real viewer.
//   key K N              hold key K (W A S D Q E) for the next N frames
//   mouse_drag DX DY     drag with the left button by DX, DY window pixels during the next frame
//   wheel N              scroll N steps (camera speed)
//   set NAME=VALUE       change a setting as the settings panel does
//   view NAME            choose the debug view (as in the view menu: display, total,
//                        gbuffer normal, reference, side by side, error heat map ...)
//   points P [C]         photon points: none, bounce, result or both, coloured by C: kind
//                        (default), direction or power (render/photon_points.h)
//   reset_camera         back to the scene camera
//   reload_shaders       what F5 does: rebuild the programs whose shader files changed
//   wait_file F          stop until file F exists (another process, e.g. a test, edits shaders
//                        meanwhile); gives up with an error after a minute
//   load_scene F         switch to scene file F, as the scene picker does
//   load_reference F     load a reference image (.pfm or .exr), as --reference does
//   render_reference on|off  path-trace the reference progressively inside the viewer
//   write_aov AOV F      write the current frame's AOV (direct, indirect, total, display) to F
//   screenshot F         write the window (UI included) as PNG to F
//   save_settings F      write the current settings as a scene `render` block (the panel's "save")
//   compute_metrics      compare the total AOV with the reference (relMSE, SSIM) and print them
//   print_panel          print the panel's messages, the window title, the camera and the
//                        Stats frame time ("panel NAME: VALUE" lines)
//   click X Y            window events, as the mouse gives them: move to X, Y (window pixels),
//                        press and release the left button
//   click_item NAME      the same on a panel widget as last drawn ("save", "save path",
//                        "view stops", "view stops help": the "(?)" on display)
//   mouse_move X Y       move the pointer to X, Y
//   press KEY            press and release KEY (A-Z, 0-9, F1-F12, Escape, Enter, Tab,
//                        Backspace), "ctrl+KEY" with Control held
//   type TEXT            the key and character events of typing TEXT (letters, digits, spaces,
//                        . _ / -)
//   frames N             let N frames pass
// Window events go through the viewer's event queue, as the real mouse and keyboard do; the
// script goes on once they have all been handed to the frames.
// Blank lines and lines starting with '#' are ignored.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ispm {

struct ScriptCommand {
    enum class Kind {
        Key,
        MouseDrag,
        Wheel,
        Set,
        View,
        Points,
        ResetCamera,
        ReloadShaders,
        WaitFile,
        LoadScene,
        LoadReference,
        RenderReference,
        WriteAov,
        Screenshot,
        SaveSettings,
        ComputeMetrics,
        PrintPanel,
        Click,
        ClickItem,
        MouseMove,
        Press,
        Type,
        Frames
    };
    Kind kind = Kind::Frames;
    std::string text;   // key, setting assignment, view, points choice, AOV name, on/off,
                        // item name, key name (upper case), typed text
    std::string path;   // write_aov, screenshot, save_settings, load_scene, load_reference,
                        // wait_file
    std::string option; // points: the colouring; press: "ctrl" or empty
    float x = 0.0f;     // drag dx, wheel steps, click and move x
    float y = 0.0f;     // drag dy, click and move y
    int frames = 0;     // frames the command lasts; 0 for instantaneous commands
    std::string where;  // "file:line" for messages
};

// Whether `name` (upper case: "F12", "ESCAPE", "W") is a key `press` knows.
bool isScriptKeyName(const std::string& name);

// Throws InputError naming file and line for an unknown command or a malformed argument.
std::vector<ScriptCommand> parseInputScript(const std::string& text, const std::string& sourceName);
std::vector<ScriptCommand> loadInputScript(const std::string& path);

// Hands out the commands frame by frame. A frame takes the next commands up to the first that
// lasts frames (key, mouse_drag, frames: held for that many frames) or through a run of outputs
// (write_aov, screenshot, save_settings, compute_metrics): commands before an output shape the
// frame it writes, commands after it start the next frame.
class ScriptPlayer {
  public:
    ScriptPlayer() = default;
    explicit ScriptPlayer(std::vector<ScriptCommand> commands) : mCommands(std::move(commands)) {}

    // The commands active during the next frame (instantaneous ones once, lasting ones every
    // frame they hold); advances by one frame.
    std::vector<const ScriptCommand*> advanceFrame();
    bool isFinished() const { return mNext >= mCommands.size() && mHeldFrames == 0; }

  private:
    std::vector<ScriptCommand> mCommands;
    size_t mNext = 0;
    const ScriptCommand* mHeld = nullptr;
    int mHeldFrames = 0;
};

} // namespace ispm
