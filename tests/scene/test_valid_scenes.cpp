// Valid scenes load with the declared defaults, derived values and resolved paths.
#include "clouds/block/spec.hpp"
#include "clouds/shell/spec.hpp"
#include "clouds/sphere/spec.hpp"
#include "clouds/vtu/spec.hpp"
#include "rkpm/scene/scene.hpp"
#include "scene_text.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace rkpm::scene {
namespace {

using testing::kBase;
using testing::kLceBody;
using testing::replaced;
namespace fs = std::filesystem;

TEST(ValidScene, DefaultsFillEveryUnwrittenKey) {
  const Scene s = parse_scene(kBase, "ok.toml");
  EXPECT_EQ(s.file, "ok.toml");
  EXPECT_EQ(s.scene.text("name"), "t");
  EXPECT_EQ(s.scene.text("description"), "");
  EXPECT_EQ(s.integrator.choice("mode"), "dynamic");
  EXPECT_EQ(s.integrator.real("t_end"), 1.0);
  EXPECT_EQ(s.integrator.real("dt"), 0.0);
  EXPECT_EQ(s.integrator.real("dt_safety"), 0.5);
  EXPECT_EQ(s.integrator.real("damping"), 0.0);
  EXPECT_EQ(s.integrator.integer("max_steps"), 10000000);
  EXPECT_EQ(s.integrator.real("relax_force_tol"), 1e-6);
  EXPECT_EQ(s.integrator.real("relax_velocity_tol"), 1e-8);
  EXPECT_EQ(s.integrator.integer("seed"), 1);
  EXPECT_DOUBLE_EQ(s.output.real("every"), 1.0 / 50);  // derived: t_end / 50
  EXPECT_EQ(s.output.choice("cells"), "mesh");
  EXPECT_EQ(s.output.integer("checkpoint_every"), 0);

  ASSERT_EQ(s.bodies.size(), 1u);
  const BodySpec& b = s.bodies[0];
  EXPECT_EQ(b.name(), "cell");
  EXPECT_EQ(b.body.real("density"), 1000.0);
  EXPECT_EQ(b.generator(), "block");
  EXPECT_EQ(b.cloud.vec3("origin"), Vec3::Zero());
  EXPECT_EQ(b.cloud.vec3("size"), Vec3::Ones());
  EXPECT_EQ(b.cloud.int3("cells"), (Int3{2, 2, 2}));
  EXPECT_EQ(b.model(), "mooney_rivlin");
  EXPECT_EQ(b.material.real("c1"), 1000.0);  // an integer literal read as a real
  EXPECT_EQ(b.material.real("c2"), 0.0);
  EXPECT_EQ(b.material.real("lambda"), 1e5);
  EXPECT_EQ(b.material.choice("grade_axis"), "none");
  EXPECT_EQ(b.material_sections.count("director"), 0u);  // only LCE bodies have a director
  EXPECT_EQ(b.rk.choice("kernel"), "cubic");
  EXPECT_EQ(b.rk.real("support"), 2.0);
  EXPECT_EQ(b.rk.choice("basis"), "linear");
  EXPECT_EQ(b.rk.choice("integration"), "scni");
  EXPECT_EQ(b.initial.vec3("velocity"), Vec3::Zero());
  EXPECT_EQ(b.initial.vec3("stretch"), Vec3::Ones());
  EXPECT_TRUE(b.boundaries.empty());
  EXPECT_TRUE(s.terms.empty());              // nothing declared, nothing to build
  EXPECT_TRUE(s.terms_of("contact").empty());
  EXPECT_EQ(b.surfaces(), (std::vector<std::string>{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}));
}

TEST(ValidScene, RemembersWhereEachValueCameFrom) {
  const Scene s = parse_scene(kBase, "ok.toml");
  const BodySpec& b = s.bodies[0];
  EXPECT_TRUE(b.cloud.given("size"));
  EXPECT_EQ(b.cloud.line("size"), 9);
  EXPECT_FALSE(b.cloud.given("origin"));
  EXPECT_EQ(b.cloud.line("origin"), 7);  // defaulted: the table's line
  EXPECT_EQ(b.cloud.variant(), "block");
  EXPECT_EQ(b.material.section(), "body.material");
}

TEST(ValidScene, LceBodyGetsDefaultDirector) {
  const Scene s = parse_scene(kBase + kLceBody, "ok.toml");
  ASSERT_EQ(s.bodies.size(), 2u);
  const BodySpec& gel = s.bodies[1];
  EXPECT_EQ(gel.model(), "lce");
  EXPECT_EQ(gel.material.real("mu"), 1000.0);
  EXPECT_EQ(gel.material.real("s"), 2.0);
  EXPECT_EQ(gel.material.real("zeta"), 0.0);
  ASSERT_EQ(gel.material_sections.count("director"), 1u);
  EXPECT_EQ(gel.material_section("director").choice("initial"), "surface_normal");
  EXPECT_EQ(gel.material_section("director").choice("boundary"), "normal");
  EXPECT_TRUE(gel.material_section("director").flag("evolve"));
  EXPECT_EQ(gel.surfaces(), std::vector<std::string>{"surface"});
  EXPECT_EQ(s.find_body("gel"), &gel);
  EXPECT_EQ(s.find_body("nobody"), nullptr);
}

TEST(ValidScene, NeoHookeanBodyTakesLameConstants) {
  const std::string text = replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000\nlambda = 1e5",
                                    "model = \"neo_hookean\"\nmu = 2000\nlambda = 8e3");
  const Scene s = parse_scene(text, "ok.toml");
  ASSERT_EQ(s.bodies.size(), 1u);
  const BodySpec& b = s.bodies[0];
  EXPECT_EQ(b.model(), "neo_hookean");
  EXPECT_EQ(b.material.real("mu"), 2000.0);
  EXPECT_EQ(b.material.real("lambda"), 8e3);
  EXPECT_TRUE(b.material_sections.empty());  // no director: the neo-Hookean table takes none
}

TEST(ValidScene, TermsKeepFileOrderAndDerivedDefaults) {
  const std::string text = kBase + kLceBody + R"([[term]]
type = "contact"
bodies = ["gel", "cell"]
epsilon = 1e-20
s0 = 2e-7
[[term]]
type = "body_force"
body = "gel"
acceleration = [0, 0, -9.81]
[[term]]
type = "surface_pressure"
body = "cell"
surface = "zmax"
pressure = 10
[[body.boundary]]
surface = "surface"
type = "velocity"
value = [0, 0, 1e-3]
axes = "z"
)";
  const Scene s = parse_scene(text, "ok.toml");
  ASSERT_EQ(s.terms.size(), 3u);
  EXPECT_EQ(s.terms[0].type(), "contact");
  EXPECT_EQ(s.terms[1].type(), "body_force");
  EXPECT_EQ(s.terms[2].type(), "surface_pressure");
  const ParamSet& contact = s.terms_of("contact").at(0)->params;
  EXPECT_EQ(contact.texts("bodies"), (std::vector<std::string>{"gel", "cell"}));
  EXPECT_EQ(contact.reals("beta"), (std::vector<double>{0.0, 0.0}));
  EXPECT_DOUBLE_EQ(contact.real("cutoff"), 6e-7);  // 3 s0
  EXPECT_DOUBLE_EQ(contact.real("skin"), 1e-7);    // 0.5 s0
  EXPECT_FALSE(contact.given("cutoff"));
  EXPECT_EQ(s.terms[1].params.vec3("acceleration"), Vec3(0, 0, -9.81));
  EXPECT_EQ(s.terms[2].params.real("pressure"), 10.0);  // integer literal read as a real

  // The [[body.boundary]] after the terms belongs to the last body (TOML rules).
  ASSERT_EQ(s.bodies[1].boundaries.size(), 1u);
  const ParamSet& bc = s.bodies[1].boundaries[0];
  EXPECT_EQ(bc.choice("type"), "velocity");
  EXPECT_EQ(bc.text("axes"), "z");
  EXPECT_EQ(bc.vec3("value"), Vec3(0, 0, 1e-3));
}

TEST(ValidScene, RelaxModeNeedsNoEndTime) {
  const Scene s = parse_scene(replaced(kBase, "t_end = 1.0", "mode = \"relax\""), "ok.toml");
  EXPECT_EQ(s.integrator.choice("mode"), "relax");
  EXPECT_FALSE(s.integrator.has("t_end"));
  EXPECT_FALSE(s.output.has("every"));  // initial and final state only
}

TEST(ValidScene, ExplicitFrameIntervalIsKept) {
  const Scene s = parse_scene(kBase + "[output]\nevery = 0.25\ncells = \"points\"\n", "ok.toml");
  EXPECT_EQ(s.output.real("every"), 0.25);
  EXPECT_TRUE(s.output.given("every"));
  EXPECT_EQ(s.output.choice("cells"), "points");
}

TEST(CloudCatalog, BlockSphereAndShellSpecsCarryTheSceneValues) {
  const std::string block = replaced(kBase, "cells = [2, 2, 2]",
                                     "cells = [3, 4, 5]\norigin = [1, 2, 3]\njitter = 0.1\nseed = 7");
  const auto b = clouds::block::spec(parse_scene(block, "ok.toml").bodies[0]);
  EXPECT_EQ(b.origin, Vec3(1, 2, 3));
  EXPECT_EQ(b.size, Vec3::Ones());
  EXPECT_EQ(b.cells, (std::array<int, 3>{3, 4, 5}));
  EXPECT_EQ(b.jitter, 0.1);
  EXPECT_EQ(b.seed, 7u);

  const auto sphere = clouds::sphere::spec(parse_scene(kBase + kLceBody, "ok.toml").bodies[1]);
  EXPECT_EQ(sphere.radius, 5e-6);
  EXPECT_EQ(sphere.cells, 16);
  EXPECT_EQ(sphere.center, Vec3::Zero());

  const std::string shell = replaced(kBase, "generator = \"block\"\nsize = [1, 1, 1]\ncells = [2, 2, 2]",
                                     "generator = \"shell\"\nlayers = 3");
  const auto sh = clouds::shell::spec(parse_scene(shell, "ok.toml").bodies[0]);
  EXPECT_EQ(sh.semi_axes, Vec3(5e-6, 5e-6, 1.5e-6));
  EXPECT_EQ(sh.thickness, 0.5e-6);
  EXPECT_EQ(sh.face_cells, 32);
  EXPECT_EQ(sh.layers, 3);
}

// A scratch directory under the system's temporary directory, removed afterwards.
class SceneOnDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rkpm_scene_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "meshes");
  }
  void TearDown() override { fs::remove_all(dir_); }
  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  fs::path dir_;
};

TEST_F(SceneOnDisk, RelativeVtuPathIsResolvedAgainstTheSceneDirectory) {
  write(dir_ / "meshes" / "cell.vtu", "<VTKFile/>");  // the scene layer checks existence only
  const std::string text = replaced(kBase, "generator = \"block\"\nsize = [1, 1, 1]\ncells = [2, 2, 2]",
                                    "generator = \"vtu\"\nfile = \"meshes/cell.vtu\"\nscale = 1e-6");
  write(dir_ / "cell.toml", text);
  const Scene s = load_scene((dir_ / "cell.toml").string());
  EXPECT_EQ(fs::path(s.bodies[0].cloud_file), dir_ / "meshes" / "cell.vtu");
  const auto vtu = clouds::vtu::spec(s.bodies[0]);
  EXPECT_EQ(fs::path(vtu.path), dir_ / "meshes" / "cell.vtu");
  EXPECT_EQ(vtu.scale, 1e-6);

  // The same scene loaded from another directory does not find the mesh, and
  // says where it looked.
  fs::create_directories(dir_ / "elsewhere");
  write(dir_ / "elsewhere" / "cell.toml", text);
  try {
    load_scene((dir_ / "elsewhere" / "cell.toml").string());
    FAIL() << "a missing mesh must be an error";
  } catch (const SceneError& e) {
    const std::string resolved = (dir_ / "elsewhere" / "meshes" / "cell.vtu").string();
    EXPECT_NE(std::string(e.what()).find("expected an existing file (resolved to " + resolved + ")"), std::string::npos)
        << e.what();
  }
}

TEST_F(SceneOnDisk, MissingSceneFileIsASceneError) {
  const std::string path = (dir_ / "absent.toml").string();
  try {
    load_scene(path);
    FAIL() << "a missing scene file must be an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot read the scene file: no such file");
    EXPECT_EQ(e.line(), 0);
  }
}

TEST_F(SceneOnDisk, SyntaxErrorNamesFileAndLine) {
  const std::string path = (dir_ / "broken.toml").string();
  write(path, kBase + "c2 = [1,\n");
  try {
    load_scene(path);
    FAIL() << "a TOML syntax error must be an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_GE(e.line(), 15);
    EXPECT_NE(std::string(e.what()).find(path + ":"), std::string::npos) << e.what();
  }
}

// The complete example scenes of the format documentation (the blocks that start
// with [scene] and declare a body) must stay valid.
TEST(ValidScene, DocumentationExamplesLoad) {
  std::ifstream in(std::string(RKPM_SOURCE_DIR) + "/docs/guide/scenes.md");
  ASSERT_TRUE(in) << "docs/guide/scenes.md not found";
  std::vector<std::string> complete;
  std::string line, block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```toml") {
      inside = true;
      block.clear();
    } else if (inside && line == "```") {
      inside = false;
      if (block.rfind("[scene]", 0) == 0 && block.find("[[body]]") != std::string::npos) complete.push_back(block);
    } else if (inside) {
      block += line + "\n";
    }
  }
  ASSERT_GE(complete.size(), 2u);
  for (const auto& scene : complete) {
    try {
      parse_scene(scene, "docs/example.toml");
    } catch (const SceneError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
}  // namespace rkpm::scene
