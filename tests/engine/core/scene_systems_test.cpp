// Which systems loadScene creates: a system the program lacks is an error at the manifest's entry,
// except rendering and audio in a headless program; "scripting" is created only when the manifest
// names a script, "meshes" only for a level drawn on a mesh.
#include <gtest/gtest.h>

#include "platon/core/scene.h"
#include "platon/testing/temp_folder.h"

namespace platon::core {
namespace {

using Folder = testing::TempFolder;

class Counted : public System {};

// A registry of stand-ins for `names`, counting what it creates.
SystemRegistry registryOf(std::initializer_list<const char*> names, std::map<std::string, int>& created) {
  SystemRegistry registry;
  for (const char* name : names)
    registry.add(name, [&created, name](Scene&) {
      ++created[name];
      return std::make_unique<Counted>();
    });
  return registry;
}

std::string errorOf(const std::string& manifest, const SystemRegistry& registry) {
  try {
    loadScene(manifest, registry);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(loaded)";
}

// Audio, like rendering, is the window's: a headless program leaves it out (the scene's own record
// of its sounds is the null device), and a program that offers it creates it.
TEST(SceneSystems, AudioIsCreatedWhereTheProgramOffersItAndLeftOutHeadless) {
  Folder folder("systems_audio");
  std::map<std::string, int> created;
  const std::string manifest = folder.write("scene.lua", "return {\n  systems = { 'rendering', 'audio' },\n}\n");
  EXPECT_EQ(loadScene(manifest, registryOf({}, created))->systemCount(), 0u);
  const auto scene = loadScene(manifest, registryOf({"rendering", "audio"}, created));
  EXPECT_NE(scene->findSystem("audio"), nullptr);
  EXPECT_EQ(created["audio"], 1);
}

TEST(SceneSystems, ASystemTheProgramLacksIsAnErrorButRenderingHeadlessIsLeftOut) {
  Folder folder("systems_missing");
  std::map<std::string, int> created;
  const std::string scripted =
      folder.write("a.lua", "return { systems = { 'scripting', 'rendering' }, scripts = { level = 'level.lua' } }\n");
  EXPECT_EQ(errorOf(scripted, registryOf({"rendering"}, created)),
            scripted + ":1:22: scripting: this program provides no such system (it provides: rendering)");
  // Headless: no renderer in the registry, and the scene loads without one.
  const auto scene = loadScene(scripted, registryOf({"scripting"}, created));
  EXPECT_EQ(scene->systemCount(), 1u);
  EXPECT_EQ(scene->findSystem("rendering"), nullptr);
  EXPECT_EQ(created["scripting"], 1);
}

TEST(SceneSystems, ScriptingWithoutScriptsCreatesNoLuaState) {
  Folder folder("systems_no_scripts");
  std::map<std::string, int> created;
  const SystemRegistry registry = registryOf({"scripting", "meshes"}, created);
  const auto bare = loadScene(folder.write("a.lua", "return { systems = { 'scripting' } }\n"), registry);
  EXPECT_EQ(created["scripting"], 0);
  EXPECT_EQ(bare->findSystem("scripting"), nullptr);
  loadScene(folder.write("b.lua", "return { systems = { 'scripting' }, scripts = { mods = { 'm.lua' } } }\n"),
            registry);
  EXPECT_EQ(created["scripting"], 1);
}

TEST(SceneSystems, MeshesAreCreatedOnlyForALevelDrawnOnAMesh) {
  Folder folder("systems_meshes");
  std::map<std::string, int> created;
  const auto scene = loadScene(folder.write("a.lua", "return { systems = { 'meshes' }, stage = { solid = 'cube' } }\n"),
                               registryOf({"meshes"}, created));
  EXPECT_EQ(created["meshes"], 0);
  EXPECT_EQ(scene->findSystem("meshes"), nullptr);
}

}  // namespace
}  // namespace platon::core
