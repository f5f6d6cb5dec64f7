#include "platon/core/scene.h"

#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "platon/core/mesh_source.h"
#include "platon/core/world_drawing.h"
#include "platon/files/read_file.h"
#include "platon/stage/mesh.h"

namespace platon::core {

static_assert(kMaxMeshFileTriangles == stage::kMaxMeshTriangles, "the plugin's cap is the stage builder's");

void Scene::addSystem(std::unique_ptr<System> system, std::string name) {
  systems_.push_back(std::move(system));
  names_.push_back(std::move(name));
}

System* Scene::findSystem(std::string_view name) {
  for (size_t i = 0; i < systems_.size(); ++i)
    if (names_[i] == name) return systems_[i].get();
  return nullptr;
}

physics::SolveReport Scene::step(const InputFrame& input) {
  std::exception_ptr first;
  auto guarded = [&](auto&& call) {
    try {
      call();
    } catch (...) {
      if (!first) first = std::current_exception();
    }
  };
  sounds_.clearFrame();
  for (const auto& s : systems_) guarded([&] { s->beforeStep(*this, input); });
  physics::SolveReport report{};
  guarded([&] { report = world_.solve(); });  // the world finishes its frame before rethrowing
  for (const auto& s : systems_) guarded([&] { s->afterStep(*this); });
  const SoundFrame heard{world_.frame(), sounds_.thisFrame(), sounds_.music(), sounds_.bank()};
  for (const auto& s : systems_) guarded([&] { s->hear(heard); });
  if (first) std::rethrow_exception(first);
  return report;
}

void Scene::draw(DrawList& out) const {
  if (!out.enabled()) return;
  drawWorld(world_, looks_, *tags_, out);
  for (const auto& s : systems_) s->draw(*this, out);
}

namespace {
stage::Solid manifestSolid(const SceneManifest& manifest) {
  return solidOfManifest(manifest.solid).value_or(stage::Solid::Hexahedron);
}

// A mesh level's stage: the mesh file read by the meshes plugin, which the manifest must name.
stage::Stage meshStage(const stage::Level& level, const SceneManifest& manifest, const SystemRegistry& registry,
                       Scene& scene) {
  if (!manifest.needs("meshes"))
    throw stage::StageError({level.file, 1, 1},
                            "the level is drawn on a mesh: the scene's manifest must list \"meshes\" in its systems");
  if (!scene.findSystem("meshes")) scene.addSystem(registry.create("meshes", scene), "meshes");
  MeshSource* source = scene.findSystem("meshes")->meshSource();
  if (!source) throw stage::StageError({level.file, 1, 1}, "the meshes system reads no meshes");
  return meshStageOf(level, *source);
}

// "file:line:column" of the manifest's entry naming `system` in its systems list, or the file.
std::string systemEntry(const SceneManifest& manifest, const std::string& system) {
  try {
    const DataValue root = readLuaData(files::readBoundedFile(manifest.path, kMaxManifestBytes), manifest.path);
    if (const DataValue* list = root.field("systems"))
      for (const DataEntry& e : list->entries)
        if (e.value.isString() && e.value.text == system)
          return manifest.path + ":" + std::to_string(e.value.line) + ":" + std::to_string(e.value.column);
  } catch (const std::exception&) {}
  return manifest.path;
}

// The sounds a scene may play: the engine's bank and the level's own, read only by a scene that
// can make a sound (one with scripts or audio); the manifest's tune must be in them.
void loadSounds(const SceneManifest& manifest, Scene& scene) {
  if (!manifest.needs("scripting") && !manifest.needs("audio")) return;
  SoundBank bank = engineSoundBank();
  if (!manifest.soundBank.empty()) {
    // A file that is none (missing, a folder, too big) is the naming field's error; a bad field in
    // it is the bank's own, at its place.
    try {
      files::checkBoundedFile(manifest.soundBank, kMaxSoundBankBytes);
    } catch (const files::FileError& e) {
      throw std::runtime_error(manifest.placeOf.at(manifest.soundBank) + ": " + manifest.soundBank +
                               ": the sound bank: " + e.reason());
    }
    readSoundBank(manifest.soundBank, bank);
  }
  if (!manifest.music.empty() && !bank.hasMusic(manifest.music)) {
    throw std::runtime_error(manifest.musicPlace + ": music '" + manifest.music +
                             "': no such tune (known: " + bank.musicNames() + ")");
  }
  scene.sounds().setBank(std::move(bank));
  scene.sounds().setMusic(manifest.music);
}

bool hasScripts(const SceneManifest& m) {
  return !m.rules.empty() || !m.player.empty() || !m.progression.empty() || !m.level.empty() || !m.mods.empty();
}

// Whether loadScene creates the named system now. "meshes" is created only for a level drawn on
// a mesh (meshStage), so other scenes never load its plugin and assimp; "scripting" only when
// the manifest names a script, so a scene without scripts never creates a Lua state; "rendering"
// and "audio" are left out where the program has no window (headless runs). Any other system the program
// does not provide is an error at the manifest's entry: the scene would silently go without it.
bool shouldCreate(const std::string& name, const SceneManifest& manifest, const SystemRegistry& registry) {
  if (name == "meshes") return false;
  if (name == "scripting" && !hasScripts(manifest)) return false;
  if (registry.has(name)) return true;
  if (name == "rendering" || name == "audio") return false;  // headless: the scene's own record is the null device
  std::string known;
  for (const std::string& n : registry.names()) known += (known.empty() ? "" : ", ") + n;
  throw std::runtime_error(systemEntry(manifest, name) + ": " + name +
                           ": this program provides no such system (it provides: " + (known.empty() ? "none" : known) +
                           ")");
}

}  // namespace

stage::MeshData meshDataOf(const MeshFile& file) {
  stage::MeshData mesh;
  for (size_t i = 0; i + 2 < file.positions.size(); i += 3)
    mesh.positions.emplace_back(file.positions[i], file.positions[i + 1], file.positions[i + 2]);
  for (size_t i = 0; i + 2 < file.triangles.size(); i += 3)
    mesh.triangles.push_back({file.triangles[i], file.triangles[i + 1], file.triangles[i + 2]});
  return mesh;
}

namespace {

// The mesh file a level names, as a canonical path: it must be a regular file inside the level's
// own folder once every symbolic link is followed (the parser refuses '..' and absolute names; a
// link could still lead anywhere, /dev/zero or /etc/passwd included).
std::string meshFileOf(const stage::Level& level) {
  namespace fs = std::filesystem;
  const fs::path folder =
      fs::path(level.file).parent_path().empty() ? fs::path(".") : fs::path(level.file).parent_path();
  const std::string shown = level.file.substr(0, level.file.find_last_of('/') + 1) + level.mesh;
  auto refuse = [&](const std::string& why) {
    throw stage::StageError({level.file, level.meshLine, level.meshColumn}, shown + ": " + why);
  };
  std::error_code error;
  const fs::path root = fs::canonical(folder, error);
  if (error) refuse("cannot find the level's folder");
  const fs::path file = fs::canonical(folder / level.mesh, error);
  if (error) refuse("cannot find the mesh file");
  const fs::path inside = file.lexically_relative(root);
  if (inside.empty() || *inside.begin() == "..")
    refuse("the mesh file leads out of the level's folder (to " + file.string() +
           "): it must be a file in that folder");
  try {
    files::checkBoundedFile(file.string(), kMaxMeshFileBytes);
  } catch (const files::FileError& e) {
    refuse("the mesh file (" + file.string() + "): " + e.reason());
  }
  return file.string();
}

}  // namespace

stage::Stage meshStageOf(const stage::Level& level, MeshSource& source) {
  const std::string folder = level.file.substr(0, level.file.find_last_of('/') + 1);
  const std::string path = meshFileOf(level);
  MeshFile file;
  try {
    file = source.loadMesh(path);
  } catch (const std::runtime_error& e) {  // "path: reason", named as the level names it
    std::string why = e.what();
    if (why.rfind(path + ": ", 0) == 0) why = folder + level.mesh + why.substr(path.size());
    throw stage::StageError({level.file, level.meshLine, level.meshColumn}, why);
  }
  try {
    return stage::stageFromPolyhedron(stage::polyhedronFromMesh(meshDataOf(file), level.size));
  } catch (const stage::StageError& e) {
    throw stage::StageError({level.file, level.meshLine, level.meshColumn}, folder + level.mesh + ": " + e.reason());
  }
}

// The scene's scripting system, made before the level file is read (and not yet in the scene's
// order): its mods may declare the tag words the level writes. Nothing when it has no scripts.
static std::unique_ptr<System> scriptsDeclaringTags(Scene& scene, const SystemRegistry& registry) {
  const SceneManifest& manifest = scene.manifest();
  if (!manifest.needs("scripting") || !shouldCreate("scripting", manifest, registry)) return nullptr;
  std::unique_ptr<System> scripting = registry.create("scripting", scene);
  auto tags = std::make_shared<stage::TagTable>(*stage::gameTags());
  scripting->declareTags(scene, *tags);
  scene.setTags(std::move(tags));
  return scripting;
}

stage::Stage levelStage(const stage::Level& level, const SystemRegistry& registry, Scene& scene) {
  return level.solid ? stage::platonicStageOf(level) : meshStage(level, scene.manifest(), registry, scene);
}

std::shared_ptr<const stage::TagTable> sceneTags(const std::string& manifestPath, const SystemRegistry& registry) {
  Scene scene;
  scene.setManifest(loadManifest(manifestPath));
  scriptsDeclaringTags(scene, registry);
  return scene.tags();
}

std::unique_ptr<Scene> loadScene(const std::string& manifestPath, const SystemRegistry& registry, Scene* replacing,
                                 const LevelOverride* override) {
  auto scene = std::make_unique<Scene>();
  scene->setManifest(loadManifest(manifestPath));
  const SceneManifest& manifest = scene->manifest();
  const auto gravity = static_cast<int64_t>(std::llround(manifest.gravity * 65536.0));
  std::unique_ptr<System> scripting = scriptsDeclaringTags(*scene, registry);
  if (!manifest.levelFile.empty()) {
    // Parsed and checked whole before anything enters the world: a bad file builds nothing.
    std::string text;
    try {
      text = override && override->text ? *override->text : stage::readLevelFile(manifest.levelFile);
    } catch (const stage::StageError& e) {  // a file that is no level file is the naming line's error
      const auto place = manifest.placeOf.find(manifest.levelFile);
      throw std::runtime_error((place == manifest.placeOf.end() ? manifestPath : place->second) + ": " + e.what());
    }
    stage::Level level = stage::parseLevel(text, manifest.levelFile, scene->tags());
    if (override && override->start) {  // the start's line stays the one errors about it name
      level.start.face = override->start->face;
      level.start.position = override->start->position;
    }
    stage::Stage solid = levelStage(level, registry, *scene);
    stage::checkLevelOnStage(level, solid);
    stage::buildLevel(level, solid, scene->world(), 0, gravity);
    scene->setStage(std::move(solid));
    scene->setLevel(std::move(level));
  } else {
    stage::Stage solid = stage::platonicStage(manifestSolid(manifest), manifest.edge);
    stage::addStageToWorld(solid, scene->world(), 0);
    scene->setStage(std::move(solid));
    for (size_t i = 0; i < scene->stage()->faceCount(); ++i)
      scene->world().mapPart(scene->stage()->part(i)).setGravity({0, -gravity});
  }
  loadSounds(manifest, *scene);
  for (const std::string& name : manifest.systems) {
    if (name == "scripting" && scripting)
      scene->addSystem(std::move(scripting), name);
    else if (shouldCreate(name, manifest, registry) && !scene->findSystem(name))
      scene->addSystem(registry.create(name, *scene), name);
  }
  for (size_t i = 0; replacing && i < scene->systemCount(); ++i)
    if (System* old = replacing->findSystem(scene->systemName(i)); old && !scene->systemName(i).empty())
      scene->system(i).carryBeforeBuild(*old);
  for (size_t i = 0; i < scene->systemCount(); ++i) scene->system(i).build(*scene);
  for (size_t i = 0; i < scene->stage()->faceCount(); ++i) scene->world().mapPart(scene->stage()->part(i)).initialize();
  for (size_t i = 0; i < scene->systemCount(); ++i) scene->system(i).start(*scene);
  return scene;
}

}  // namespace platon::core
