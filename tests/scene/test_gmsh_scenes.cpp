// Scenes whose clouds come from Gmsh files: the file's physical surfaces are the names
// the body's boundary conditions and terms may use, and a file the scene cannot use is
// reported with the scene's file, line and key before anything runs.
#include "rkpm/scene/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace rkpm::scene {
namespace {

namespace fs = std::filesystem;

// One directory per test: ctest runs the tests of this file as separate processes in
// parallel, and each writes its own box.geo; a shared directory let one test truncate
// the file while another read it.
fs::path test_dir() {
  return fs::path(::testing::TempDir()) / "rkpm_gmsh_scenes" /
         ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

void write(const std::string& name, const std::string& text) {
  fs::create_directories(test_dir());
  std::ofstream(test_dir() / name) << text;
}

const std::string kGeo = R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Physical Surface("bottom") = Surface In BoundingBox{-0.01, -0.01, -0.01, 2.01, 1.01, 0.01};
Physical Surface("ends") = Surface In BoundingBox{-0.01, -0.01, -0.01, 0.01, 1.01, 1.01};
)";

// A scene whose body is the Gmsh file `file`, with `cloud_extra` in [body.cloud] and
// `rest` appended.
std::string scene_text(const std::string& file, const std::string& cloud_extra, const std::string& rest) {
  return "[scene]\nname = \"g\"\n[integrator]\nt_end = 1.0\n[[body]]\nname = \"cell\"\n[body.cloud]\n"
         "generator = \"gmsh\"\nfile = \"" + file + "\"\n" + cloud_extra +
         "[body.material]\nmodel = \"neo_hookean\"\nmu = 1000\nlambda = 4000\n" + rest;
}

Scene load(const std::string& name, const std::string& text) {
  write(name, text);
  return load_scene((test_dir() / name).string());
}

void expect_error(const std::string& name, const std::string& text, const std::string& message) {
  try {
    load(name, text);
    FAIL() << "accepted " << name;
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(GmshScene, ThePhysicalSurfacesNameTheBodysSurfaces) {
  write("box.geo", kGeo);
  const Scene s = load("ok.toml", scene_text("box.geo", "mesh_size = 0.5\n",
                                             "[[body.boundary]]\nsurface = \"bottom\"\n[[term]]\n"
                                             "type = \"surface_pressure\"\nbody = \"cell\"\nsurface = \"ends\"\n"
                                             "pressure = 10\n"));
  EXPECT_EQ(s.bodies[0].surfaces(), (std::vector<std::string>{"surface", "bottom", "ends"}));
  EXPECT_EQ(s.bodies[0].cloud_file, (test_dir() / "box.geo").lexically_normal().string());
}

TEST(GmshScene, ASurfaceTheFileDoesNotNameIsAnError) {
  write("box.geo", kGeo);
  expect_error("missing.toml", scene_text("box.geo", "mesh_size = 0.5\n", "[[body.boundary]]\nsurface = \"top\"\n"),
               "missing.toml:16: [body.boundary] surface = \"top\": expected a surface of body \"cell\" (generator = "
               "\"gmsh\"): \"surface\", \"bottom\", \"ends\", \"all\"");
}

TEST(GmshScene, FilesItCannotUseAreErrors) {
  write("box.geo", kGeo);
  expect_error("no_size.toml", scene_text("box.geo", "", ""),
               "no_size.toml:9: [body.cloud] file = \"box.geo\": expected a mesh_size key beside a .geo file");
  write("shape.stl", "solid x\nendsolid x\n");
  expect_error("stl.toml", scene_text("shape.stl", "", ""),
               "stl.toml:9: [body.cloud] file = \"shape.stl\": expected a Gmsh file named *.msh (a mesh) or *.geo");
  write("garbage.msh", "not a mesh at all\n");
  expect_error("garbage.toml", scene_text("garbage.msh", "", ""),
               "garbage.toml:9: [body.cloud] file = \"garbage.msh\": expected a file Gmsh can read: Gmsh file '");
  expect_error("absent.toml", scene_text("absent.msh", "", ""),
               "absent.toml:9: [body.cloud] file = \"absent.msh\": expected an existing file");
  expect_error("levels.toml",
               "[scene]\nname = \"g\"\n[integrator]\nmode = \"relax\"\nnested_levels = [0.5]\n[[body]]\nname = \"cell\"\n"
               "[body.cloud]\ngenerator = \"gmsh\"\nfile = \"box.geo\"\nmesh_size = 0.5\n[body.material]\n"
               "model = \"neo_hookean\"\nmu = 1000\nlambda = 4000\n",
               "levels.toml:5: [integrator] nested_levels = [0.5]: expected [] when a body's cloud is imported (body "
               "\"cell\", generator = \"gmsh\" at line 9)");
}

}  // namespace
}  // namespace rkpm::scene
