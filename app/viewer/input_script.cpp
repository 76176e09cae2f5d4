// Parsing and replaying viewer scripts.
#include "viewer/input_script.h"

#include "core/input_error.h"
#include "core/strings.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace ispm {
namespace {

constexpr const char* kKeys = "WASDQE";

int parseCount(std::istringstream& in, const std::string& where, const char* what) {
    long long value = -1;
    if (!(in >> value) || value < 0 || value > 1000000) {
        throw InputError(strCat(where, ": expected ", what, " (a count from 0 to 1000000)"));
    }
    return static_cast<int>(value);
}

float parseFloat(std::istringstream& in, const std::string& where, const char* what) {
    float value = 0.0f;
    if (!(in >> value)) throw InputError(strCat(where, ": expected ", what, " (a number)"));
    return value;
}

std::string parseWord(std::istringstream& in, const std::string& where, const char* what) {
    std::string word;
    if (!(in >> word)) throw InputError(strCat(where, ": expected ", what));
    return word;
}

std::string toUpper(std::string text) {
    for (char& ch : text)
        ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return text;
}

bool isTypable(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string(" ._/-").find(c) != std::string::npos;
}

ScriptCommand parseLine(const std::string& command, std::istringstream& in,
                        const std::string& where) {
    using Kind = ScriptCommand::Kind;
    ScriptCommand c;
    c.where = where;
    if (command == "key") {
        c.kind = Kind::Key;
        c.text = parseWord(in, where, "a key (W A S D Q E)");
        for (char& ch : c.text)
            ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        if (c.text.size() != 1 || std::string(kKeys).find(c.text[0]) == std::string::npos) {
            throw InputError(
                strCat(where, ": expected a key among W A S D Q E, got '", c.text, "'"));
        }
        c.frames = parseCount(in, where, "the frames to hold the key");
    } else if (command == "mouse_drag") {
        c.kind = Kind::MouseDrag;
        c.x = parseFloat(in, where, "the drag's dx in pixels");
        c.y = parseFloat(in, where, "the drag's dy in pixels");
        c.frames = 1;
    } else if (command == "wheel") {
        c.kind = Kind::Wheel;
        c.x = parseFloat(in, where, "the scroll steps");
    } else if (command == "set") {
        c.kind = Kind::Set;
        c.text = parseWord(in, where, "name=value");
    } else if (command == "view") {
        c.kind = Kind::View;
        std::getline(in >> std::ws, c.text);
        if (c.text.empty()) throw InputError(strCat(where, ": expected a view name"));
    } else if (command == "points") {
        c.kind = Kind::Points;
        c.text = parseWord(in, where, "none, bounce, result or both");
        if (c.text != "none" && c.text != "bounce" && c.text != "result" && c.text != "both") {
            throw InputError(
                strCat(where, ": expected none, bounce, result or both, got '", c.text, "'"));
        }
        c.option = "kind";
        if (in >> c.option && c.option != "kind" && c.option != "direction" &&
            c.option != "power") {
            throw InputError(strCat(
                where, ": expected the colouring kind, direction or power, got '", c.option, "'"));
        }
    } else if (command == "reset_camera") {
        c.kind = Kind::ResetCamera;
    } else if (command == "reload_shaders") {
        c.kind = Kind::ReloadShaders;
    } else if (command == "wait_file") {
        c.kind = Kind::WaitFile;
        c.path = parseWord(in, where, "a file to wait for");
    } else if (command == "load_scene") {
        c.kind = Kind::LoadScene;
        c.path = parseWord(in, where, "a scene file (.json)");
    } else if (command == "load_reference") {
        c.kind = Kind::LoadReference;
        c.path = parseWord(in, where, "a reference image (.pfm or .exr)");
    } else if (command == "render_reference") {
        c.kind = Kind::RenderReference;
        c.text = parseWord(in, where, "on or off");
        if (c.text != "on" && c.text != "off") {
            throw InputError(strCat(where, ": expected on or off, got '", c.text, "'"));
        }
    } else if (command == "compute_metrics") {
        c.kind = Kind::ComputeMetrics;
    } else if (command == "write_aov") {
        c.kind = Kind::WriteAov;
        c.text = parseWord(in, where, "an AOV (direct, indirect, total or display)");
        c.path = parseWord(in, where, "an output file");
    } else if (command == "screenshot") {
        c.kind = Kind::Screenshot;
        c.path = parseWord(in, where, "an output .png file");
    } else if (command == "save_settings") {
        c.kind = Kind::SaveSettings;
        c.path = parseWord(in, where, "an output .json file");
    } else if (command == "print_panel") {
        c.kind = Kind::PrintPanel;
    } else if (command == "click" || command == "mouse_move") {
        c.kind = command == "click" ? Kind::Click : Kind::MouseMove;
        c.x = parseFloat(in, where, "x in window pixels");
        c.y = parseFloat(in, where, "y in window pixels");
    } else if (command == "click_item") {
        c.kind = Kind::ClickItem;
        std::getline(in >> std::ws, c.text);
        if (c.text.empty()) throw InputError(strCat(where, ": expected a panel item's name"));
    } else if (command == "press") {
        c.kind = Kind::Press;
        c.text = toUpper(parseWord(in, where, "a key"));
        if (c.text.starts_with("CTRL+")) {
            c.option = "ctrl";
            c.text = c.text.substr(5);
        }
        if (!isScriptKeyName(c.text)) {
            throw InputError(strCat(where,
                                    ": expected a key (A-Z, 0-9, F1-F12, Escape, Enter, "
                                    "Tab, Backspace, optionally ctrl+), got '",
                                    c.text, "'"));
        }
    } else if (command == "type") {
        c.kind = Kind::Type;
        std::getline(in, c.text);
        if (!c.text.empty() && c.text[0] == ' ') c.text.erase(0, 1); // the separator
        if (c.text.empty()) throw InputError(strCat(where, ": expected the text to type"));
        for (char ch : c.text) {
            if (!isTypable(ch)) {
                throw InputError(strCat(where, ": cannot type '", std::string(1, ch),
                                        "' (letters, digits, spaces and . _ / - only)"));
            }
        }
    } else if (command == "frames") {
        c.kind = Kind::Frames;
        c.frames = parseCount(in, where, "the frames to wait");
    } else {
        throw InputError(strCat(
            where, ": unknown command '", command,
            "' (expected key, mouse_drag, wheel, set, view, points, reset_camera, reload_shaders, "
            "wait_file, load_scene, load_reference, render_reference, write_aov, screenshot, "
            "save_settings, "
            "compute_metrics, print_panel, click, click_item, mouse_move, press, type or "
            "frames)"));
    }
    std::string extra;
    if (c.kind != Kind::View && c.kind != Kind::ClickItem && c.kind != Kind::Type && in >> extra) {
        throw InputError(strCat(where, ": unexpected '", extra, "' after the command"));
    }
    return c;
}

bool isOutput(const ScriptCommand& c) {
    using Kind = ScriptCommand::Kind;
    return c.kind == Kind::WriteAov || c.kind == Kind::Screenshot || c.kind == Kind::SaveSettings ||
           c.kind == Kind::ComputeMetrics || c.kind == Kind::PrintPanel;
}

} // namespace

bool isScriptKeyName(const std::string& name) {
    if (name.size() == 1) return std::isalnum(static_cast<unsigned char>(name[0])) != 0;
    if (name == "ESCAPE" || name == "ENTER" || name == "TAB" || name == "BACKSPACE") return true;
    if (name.size() < 2 || name[0] != 'F') return false;
    const std::string digits = name.substr(1);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 2) {
        return false;
    }
    const int number = std::stoi(digits);
    constexpr int kFunctionKeys = 12;
    return number >= 1 && number <= kFunctionKeys;
}

std::vector<ScriptCommand> parseInputScript(const std::string& text,
                                            const std::string& sourceName) {
    std::vector<ScriptCommand> commands;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        std::istringstream in(line);
        std::string command;
        if (!(in >> command) || command[0] == '#') continue;
        commands.push_back(parseLine(command, in, strCat(sourceName, ":", number)));
    }
    return commands;
}

std::vector<ScriptCommand> loadInputScript(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw InputError(strCat(path, ": cannot open the input script"));
    std::stringstream text;
    text << file.rdbuf();
    return parseInputScript(text.str(), path);
}

std::vector<const ScriptCommand*> ScriptPlayer::advanceFrame() {
    std::vector<const ScriptCommand*> active;
    while (mHeldFrames == 0 && mNext < mCommands.size()) {
        const ScriptCommand& c = mCommands[mNext];
        if (!active.empty() && isOutput(*active.back()) && !isOutput(c)) break;
        ++mNext;
        if (c.frames > 0) {
            mHeld = &c;
            mHeldFrames = c.frames;
        } else {
            active.push_back(&c);
        }
    }
    if (mHeldFrames > 0) {
        active.push_back(mHeld);
        --mHeldFrames;
    }
    return active;
}

} // namespace ispm
