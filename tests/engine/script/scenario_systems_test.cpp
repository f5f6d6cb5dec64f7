// A headless scenario on a Platonic level whose manifest lists "meshes" loads neither the meshes
// plugin nor assimp: the plugin is loaded only for a level drawn on a mesh. In a fresh process.
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/script/scenario.h"
#include "platon/testing/mapped.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

using testing::mapped;

TEST(ScenarioSystems, MeshesListedForAPlatonicLevelLoadNoAssimp) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  testing::TempFolder folder("systems_meshes_listed");
  folder.write("scene.lua",
               "return { systems = { 'scripting', 'meshes' }, stage = { solid = 'cube' },\n"
               "  scripts = { preset = 'game', level = 'level.lua' } }\n");
  folder.write("level.lua",
               "return { start = { face = 0, x = 600, y = 700 },\n"
               "  build = function(game) game.world.line(0, 0, 512, 4096, 512) end }\n");
  const std::string scenario = folder.write("run.lua", "return { scene = 'scene.lua', frames = 30 }\n");
  EXPECT_EXIT(
      {
        RunOptions options;
        options.pluginFolders = {PLATON_PLUGIN_DIR};
        const ScenarioResult r = runScenario(scenario, options);
        if (!r.passed) {
          std::fprintf(stderr, "%s\n", r.message.c_str());
          std::exit(2);
        }
        std::exit(mapped("libassimp") || mapped("platon_meshes") ? 1 : 0);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace platon::script
