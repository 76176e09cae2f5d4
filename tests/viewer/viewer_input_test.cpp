// The viewer's pure parts (no window): script parsing and replay, the fly camera, the saved
// render block. They run in the same binary as the window tests, under xvfb-run.
#include "core/input_error.h"
#include "settings/settings.h"
#include "viewer/fly_camera.h"
#include "viewer/input_script.h"
#include "viewer/settings_panel.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ispm::test {
namespace {

using Kind = ScriptCommand::Kind;

TEST(InputScript, ParsesEveryCommand) {
    const auto commands =
        parseInputScript("# comment\n\nkey w 10\nmouse_drag 5 -3\nwheel 2\n"
                         "set photons=20000\nview gbuffer normal\nreset_camera\n"
                         "write_aov total out.pfm\nscreenshot s.png\nsave_settings r.json\n"
                         "frames 4\n",
                         "s.txt");
    ASSERT_EQ(commands.size(), 10u);
    EXPECT_EQ(commands[0].kind, Kind::Key);
    EXPECT_EQ(commands[0].text, "W");
    EXPECT_EQ(commands[0].frames, 10);
    EXPECT_EQ(commands[0].where, "s.txt:3");
    EXPECT_FLOAT_EQ(commands[1].x, 5.0f);
    EXPECT_FLOAT_EQ(commands[1].y, -3.0f);
    EXPECT_EQ(commands[1].frames, 1);
    EXPECT_EQ(commands[3].text, "photons=20000");
    EXPECT_EQ(commands[4].text, "gbuffer normal");
    EXPECT_EQ(commands[6].path, "out.pfm");
    EXPECT_EQ(commands[8].kind, Kind::SaveSettings);
    EXPECT_EQ(commands[9].frames, 4);
}

TEST(InputScript, ParsesReloadAndReferenceCommands) {
    const auto commands = parseInputScript("reload_shaders\nwait_file done\nload_reference r.pfm\n"
                                           "render_reference on\ncompute_metrics\n",
                                           "s.txt");
    ASSERT_EQ(commands.size(), 5u);
    EXPECT_EQ(commands[0].kind, Kind::ReloadShaders);
    EXPECT_EQ(commands[1].kind, Kind::WaitFile);
    EXPECT_EQ(commands[1].path, "done");
    EXPECT_EQ(commands[2].kind, Kind::LoadReference);
    EXPECT_EQ(commands[2].path, "r.pfm");
    EXPECT_EQ(commands[3].kind, Kind::RenderReference);
    EXPECT_EQ(commands[3].text, "on");
    EXPECT_EQ(commands[4].kind, Kind::ComputeMetrics);
    EXPECT_THROW(parseInputScript("render_reference maybe\n", "s.txt"), InputError);
    const auto scene = parseInputScript("load_scene other.json\n", "s.txt");
    ASSERT_EQ(scene.size(), 1u);
    EXPECT_EQ(scene[0].kind, Kind::LoadScene);
    EXPECT_EQ(scene[0].path, "other.json");
    const auto points = parseInputScript("points result\npoints bounce power\n", "s.txt");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[0].option, "kind"); // the colouring defaults to the kind's tint
    EXPECT_EQ(points[1].text, "bounce");
    EXPECT_EQ(points[1].option, "power");
    // compute_metrics is an output: it ends its frame like write_aov.
    ScriptPlayer player(parseInputScript("compute_metrics\nreset_camera\n", "s.txt"));
    EXPECT_EQ(player.advanceFrame().size(), 1u);
    EXPECT_EQ(player.advanceFrame().size(), 1u);
}

TEST(InputScript, ParsesWindowEventCommands) {
    const auto commands = parseInputScript("click 300 40\nclick_item save path\nmouse_move 5 6\n"
                                           "press f12\npress ctrl+q\ntype my file.json\n"
                                           "print_panel\n",
                                           "s.txt");
    ASSERT_EQ(commands.size(), 7u);
    EXPECT_EQ(commands[0].kind, Kind::Click);
    EXPECT_FLOAT_EQ(commands[0].x, 300.0f);
    EXPECT_FLOAT_EQ(commands[0].y, 40.0f);
    EXPECT_EQ(commands[1].kind, Kind::ClickItem);
    EXPECT_EQ(commands[1].text, "save path");
    EXPECT_EQ(commands[2].kind, Kind::MouseMove);
    EXPECT_EQ(commands[3].kind, Kind::Press);
    EXPECT_EQ(commands[3].text, "F12");
    EXPECT_EQ(commands[3].option, "");
    EXPECT_EQ(commands[4].text, "Q");
    EXPECT_EQ(commands[4].option, "ctrl");
    EXPECT_EQ(commands[5].kind, Kind::Type);
    EXPECT_EQ(commands[5].text, "my file.json");
    EXPECT_EQ(commands[6].kind, Kind::PrintPanel);
    for (const char* key : {"A", "7", "F1", "F12", "ESCAPE", "ENTER"})
        EXPECT_TRUE(isScriptKeyName(key)) << key;
    for (const char* key : {"F0", "F13", "FX", "", "SHIFT"})
        EXPECT_FALSE(isScriptKeyName(key)) << key;
}

TEST(InputScript, NamesFileAndLineOnErrors) {
    const char* bad[] = {"jump 3",
                         "key X 3",
                         "key W",
                         "key W -1",
                         "mouse_drag 1",
                         "frames 2 3",
                         "write_aov total",
                         "points sideways",
                         "points result sideways",
                         "points result power 2",
                         "click 1",
                         "click_item",
                         "press F13",
                         "press",
                         "type",
                         "type a*b",
                         "print_panel now"};
    for (const char* line : bad) {
        try {
            parseInputScript(std::string("frames 1\n") + line + "\n", "in.txt");
            ADD_FAILURE() << "accepted '" << line << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("in.txt:2"), std::string::npos) << e.what();
        }
    }
}

TEST(InputScript, PlayerHoldsLastingCommandsAndRunsOthersOnce) {
    ScriptPlayer player(parseInputScript("set seed=2\nkey W 2\nset seed=3\nframes 1\n", "s"));
    std::vector<std::vector<Kind>> frames;
    while (!player.isFinished()) {
        std::vector<Kind> kinds;
        for (const ScriptCommand* c : player.advanceFrame())
            kinds.push_back(c->kind);
        frames.push_back(kinds);
    }
    const std::vector<std::vector<Kind>> expected = {
        {Kind::Set, Kind::Key}, {Kind::Key}, {Kind::Set, Kind::Frames}};
    EXPECT_EQ(frames, expected);
    EXPECT_TRUE(player.advanceFrame().empty());
}

TEST(InputScript, OutputsEndTheirFrame) {
    ScriptPlayer player(
        parseInputScript("write_aov total a.pfm\nscreenshot b.png\nset seed=2\nframes 1\n", "s"));
    const auto first = player.advanceFrame();
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first[1]->kind, Kind::Screenshot);
    const auto second = player.advanceFrame();
    ASSERT_EQ(second.size(), 2u);
    EXPECT_EQ(second[0]->kind, Kind::Set);
    EXPECT_TRUE(player.isFinished());
}

Camera makeCamera() {
    Camera c;
    c.position = {0.0f, 1.0f, 5.0f};
    c.target = {0.0f, 1.0f, 0.0f};
    return c;
}

TEST(FlyCamera, MovesAlongTheViewAtItsSpeed) {
    const float sceneSizeM = 8.0f;
    Camera camera = makeCamera();
    FlyCamera fly(camera, sceneSizeM);
    const float seconds = 0.5f;
    fly.update({.move = {0, 0, 1}}, seconds, camera);
    const float expectedStep = fly.getSpeed() * seconds;
    EXPECT_NEAR(camera.position.z, 5.0f - expectedStep, 1e-5f);
    EXPECT_NEAR(camera.position.x, 0.0f, 1e-6f);
    fly.update({.move = {1, 1, 0}}, seconds, camera); // right is +x, up is +y
    EXPECT_NEAR(camera.position.x, expectedStep, 1e-5f);
    EXPECT_NEAR(camera.position.y, 1.0f + expectedStep, 1e-5f);
}

TEST(FlyCamera, DragTurnsWheelScalesSpeedResetRestores) {
    Camera camera = makeCamera();
    FlyCamera fly(camera, 1.0f);
    const float speed = fly.getSpeed();
    fly.update({.dragPx = {100.0f, 0.0f}, .wheel = 2.0f}, 0.0f, camera);
    EXPECT_GT(fly.getSpeed(), speed);
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    EXPECT_GT(forward.x, 0.1f); // dragging right turns right (+x when looking down -z)
    EXPECT_NEAR(glm::length(camera.target - camera.position), 5.0f, 1e-4f);
    fly.update({.dragPx = {0.0f, 100.0f}}, 0.0f, camera);
    EXPECT_LT(glm::normalize(camera.target - camera.position).y, -0.1f); // drag down looks down
    fly.reset(camera);
    EXPECT_EQ(camera.position, makeCamera().position);
    EXPECT_EQ(camera.target, makeCamera().target);
    EXPECT_FLOAT_EQ(fly.getSpeed(), speed);
}

TEST(SettingsPanel, RenderBlockRoundTripsThroughTheTable) {
    Settings s;
    s.setFromString("tonemap=filmic", "test");
    s.setFromString("photons=20000", "test");
    s.setFromString("exposure=-1.5", "test");
    const nlohmann::json block = formatRenderBlock(s);
    EXPECT_EQ(block.at("tonemap"), "filmic");
    EXPECT_EQ(block.at("photons"), 20000);
    EXPECT_DOUBLE_EQ(block.at("exposure").get<double>(), -1.5);
    const Settings without = removeSetting(s, "photons");
    EXPECT_FALSE(without.isSet("photons"));
    EXPECT_TRUE(without.isSet("tonemap"));
}

} // namespace
} // namespace ispm::test
