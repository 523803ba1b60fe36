// Every way a scene file can be wrong, with the message it must produce. Each
// expected text names file:line, the section and key, the value as written and
// what was expected, so a user can fix the file without reading the source.
#include "rkpm/scene/scene.hpp"
#include "scene_text.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

namespace rkpm::scene {
namespace {

using testing::kBase;
using testing::kLceBody;
using testing::replaced;

struct Malformed {
  const char* what;
  std::string toml;
  std::string message;  // must occur verbatim in the SceneError's message
};

const std::string kBlockCloud = "generator = \"block\"\nsize = [1, 1, 1]\ncells = [2, 2, 2]";

std::vector<Malformed> malformed_scenes() {
  const std::string term = "[[term]]\n";  // line 15 when appended to kBase
  return {
      // --- unknown keys and sections ---------------------------------------------
      {"unknown key in a variant table", kBase + "mu = 3\n",
       "bad.toml:15: [body.material] mu = 3: expected a known key for model = \"mooney_rivlin\": "
       "model, c1, c2, lambda, grade_axis, grade_a, grade_b, grade_length"},
      {"misspelt key gets a suggestion", kBase + "lamda = 5\n",
       "bad.toml:15: [body.material] lamda = 5: expected a known key for model = \"mooney_rivlin\": "
       "model, c1, c2, lambda, grade_axis, grade_a, grade_b, grade_length (did you mean \"lambda\"?)"},
      {"misspelt key of a body", replaced(kBase, "name = \"cell\"\n", "name = \"cell\"\ndensty = 3\n"),
       "bad.toml:7: [body] densty = 3: expected a known key or sub-table: name, density, cloud, material, "
       "rk, initial, boundary, director (did you mean \"density\"?)"},
      {"unknown section", kBase + "[integrater]\nseed = 2\n",
       "bad.toml:15: [integrater]: expected a known section: scene, integrator, output, body, term "
       "(did you mean \"integrator\"?)"},
      {"key outside any section", "seed = 3\n" + kBase,
       "bad.toml:1: seed = 3: expected a key inside a section"},
      {"TOML syntax error", kBase + "c2 = \n", "bad.toml:15: TOML syntax error:"},
      {"missing [scene] section", replaced(kBase, "[scene]\nname = \"t\"\n", ""),
       "bad.toml: [scene]: expected this section (required)"},
      {"[body] written as a single table", replaced(kBase, "[[body]]", "[body]"),
       "bad.toml:5: [body]: expected [[body]] (an array of tables, one per body)"},
      {"body without a material",
       replaced(kBase, "[body.material]\nmodel = \"mooney_rivlin\"\nc1 = 1000\nlambda = 1e5\n", ""),
       "bad.toml:5: [body.material]: expected this table for every body (required)"},

      // --- wrong types ------------------------------------------------------------
      {"string where a real is expected", replaced(kBase, "t_end = 1.0", "t_end = \"long\""),
       "bad.toml:4: [integrator] t_end = \"long\": expected a real > 0 [s]"},
      {"real where an integer is expected", replaced(kBase, "cells = [2, 2, 2]", "cells = [2, 2.5, 2]"),
       "bad.toml:10: [body.cloud] cells = [2, 2.5, 2]: expected an array of 3 integers, each in [1, 1048576]"},
      {"vec3 with two components", replaced(kBase, "size = [1, 1, 1]", "size = [1, 1]"),
       "bad.toml:9: [body.cloud] size = [1, 1]: expected an array of 3 reals, each > 0 [m]"},
      {"string where a boolean is expected", kBase + kLceBody + "[body.director]\nevolve = \"yes\"\n",
       "bad.toml:25: [body.director] evolve = \"yes\": expected true or false"},
      {"contact with one body", kBase + kLceBody + term +
           "type = \"contact\"\nbodies = [\"cell\"]\nepsilon = 1e-20\ns0 = 1e-7\n",
       "bad.toml:26: [term] bodies = [\"cell\"]: expected an array of 2 strings"},

      // --- out of range -----------------------------------------------------------
      {"negative end time", replaced(kBase, "t_end = 1.0", "t_end = -1"),
       "bad.toml:4: [integrator] t_end = -1: expected a real > 0 [s]"},
      {"zero component of a size", replaced(kBase, "size = [1, 1, 1]", "size = [1, 0, 1]"),
       "bad.toml:9: [body.cloud] size = [1, 0, 1]: expected an array of 3 reals, each > 0 [m]"},
      {"jitter above its maximum", replaced(kBase, "cells = [2, 2, 2]", "cells = [2, 2, 2]\njitter = 0.5"),
       "bad.toml:11: [body.cloud] jitter = 0.5: expected a real in [0, 0.3]"},
      {"not-a-number modulus", replaced(kBase, "c1 = 1000", "c1 = nan"),
       "bad.toml:13: [body.material] c1 = nan: expected a real >= 0 [Pa]"},
      {"negative seed", replaced(kBase, "t_end = 1.0", "t_end = 1.0\nseed = -4"),
       "bad.toml:5: [integrator] seed = -4: expected an integer >= 0"},

      // --- choices and required keys ----------------------------------------------
      {"misspelt generator", replaced(kBase, "generator = \"block\"", "generator = \"blok\""),
       "bad.toml:8: [body.cloud] generator = \"blok\": expected one of \"block\", \"sphere\", \"shell\", "
       "\"vtu\", \"gmsh\" (did you mean \"block\"?)"},
      {"unknown term type", kBase + term + "type = \"gravity\"\n",
       "bad.toml:16: [term] type = \"gravity\": expected one of \"body_force\", \"surface_pressure\", "
       "\"volume_constraint\", \"surface_tension\", \"contact\""},
      {"missing required key", replaced(kBase, "size = [1, 1, 1]\n", ""),
       "bad.toml:7: [body.cloud] size: expected a value for this required key: an array of 3 reals, each > 0 [m]"},
      {"missing generator", replaced(kBase, "generator = \"block\"\n", ""),
       "bad.toml:7: [body.cloud] generator: expected a value for this required key: one of \"block\""},
      {"LCE without bulk modulus", kBase + replaced(kLceBody, "bulk = 1e5\n", ""),
       "bad.toml:20: [body.material] bulk: expected a value for this required key: a real > 0 [Pa]"},

      // --- inconsistent combinations ----------------------------------------------
      {"dynamic mode without t_end", replaced(kBase, "t_end = 1.0\n", ""),
       "bad.toml:3: [integrator] t_end: expected a value when mode = \"dynamic\""},
      {"time step longer than the run", replaced(kBase, "t_end = 1.0", "t_end = 1.0\ndt = 2.0"),
       "bad.toml:5: [integrator] dt = 2: expected a time step no larger than t_end = 1 s"},
      {"frame interval longer than the run", kBase + "[output]\nevery = 2.0\n",
       "bad.toml:16: [output] every = 2: expected a frame interval no longer than [integrator] t_end = 1 s"},
      {"two bodies with one name", kBase + replaced(kLceBody, "name = \"gel\"", "name = \"cell\""),
       "bad.toml:16: [body] name = \"cell\": expected a unique body name (already used at line 6)"},
      {"director on a Mooney-Rivlin body", kBase + "[body.director]\ninitial = \"radial\"\n",
       "bad.toml:15: [body.director]: expected no director table for model = \"mooney_rivlin\" "
       "(only model = \"lce\" has a director)"},
      {"neo-Hookean without lambda",
       replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000\nlambda = 1e5\n", "model = \"neo_hookean\"\nmu = 1000\n"),
       "bad.toml:11: [body.material] lambda: expected a value for this required key: a real > 0 [Pa]"},
      {"neo-Hookean with zero shear modulus",
       replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000", "model = \"neo_hookean\"\nmu = 0"),
       "bad.toml:13: [body.material] mu = 0: expected a real > 0 [Pa]"},
      {"director on a neo-Hookean body",
       replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000", "model = \"neo_hookean\"\nmu = 1000") +
           "[body.director]\ninitial = \"radial\"\n",
       "bad.toml:15: [body.director]: expected no director table for model = \"neo_hookean\" "
       "(only model = \"lce\" has a director)"},
      {"viscoelastic with fewer relaxation times than branches",
       replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000", "model = \"viscoelastic\"\nmu = 1000\nbeta = [1, 0.5]\ntau = [1e-3]"),
       "bad.toml:15: [body.material] tau = [0.001]: expected one relaxation time per branch: 2 value(s), as beta has"},
      {"viscoelastic with five branches",
       replaced(kBase, "model = \"mooney_rivlin\"\nc1 = 1000",
                "model = \"viscoelastic\"\nmu = 1000\nbeta = [1, 1, 1, 1, 1]\ntau = [1, 1, 1, 1, 1]"),
       "bad.toml:14: [body.material] beta = [1, 1, 1, 1, 1]: expected at most 4 Maxwell branches"},
      {"fixed director of zero length",
       kBase + kLceBody + "[body.director]\ninitial = \"fixed\"\nvector = [0, 0, 0]\n",
       "bad.toml:26: [body.director] vector = [0, 0, 0]: expected a non-zero vector"},
      {"director vector without initial = fixed", kBase + kLceBody + "[body.director]\nvector = [1, 0, 0]\n",
       "bad.toml:25: [body.director] vector = [1, 0, 0]: expected no vector unless initial = \"fixed\""},
      {"shell thicker than its smallest semi-axis",
       replaced(kBase, kBlockCloud, "generator = \"shell\"\nsemi_axes = [5e-6, 5e-6, 1e-6]\nthickness = 1e-6"),
       "bad.toml:10: [body.cloud] thickness = 1e-06: expected a thickness smaller than the smallest "
       "semi-axis (1e-06 m)"},
      {"Mooney-Rivlin with c1 = c2 = 0", replaced(kBase, "c1 = 1000", "c1 = 0"),
       "bad.toml:11: [body.material] c2 = 0: expected c1 + c2 > 0 (both are zero)"},
      {"grading key without a grading axis", kBase + "grade_a = 4\n",
       "bad.toml:15: [body.material] grade_a = 4: expected no grading key unless grade_axis is"},
      {"boundary on a surface the generator lacks", kBase + "[[body.boundary]]\nsurface = \"top\"\n",
       "bad.toml:16: [body.boundary] surface = \"top\": expected a surface of body \"cell\" (generator = "
       "\"block\"): \"xmin\", \"xmax\", \"ymin\", \"ymax\", \"zmin\", \"zmax\", \"all\""},
      {"boundary axes not a subset of xyz", kBase + "[[body.boundary]]\nsurface = \"zmin\"\naxes = \"xw\"\n",
       "bad.toml:17: [body.boundary] axes = \"xw\": expected a non-empty subset of \"xyz\""},
      {"boundary value on a fixed condition",
       kBase + "[[body.boundary]]\nsurface = \"zmin\"\nvalue = [0, 0, 1]\n",
       "bad.toml:17: [body.boundary] value = [0, 0, 1]: expected no value unless type = \"velocity\""},
      {"term naming an unknown body", kBase + term + "type = \"body_force\"\nbody = \"cel\"\nacceleration = [0, 0, -9.8]\n",
       "bad.toml:17: [term] body = \"cel\": expected the name of a declared body: \"cell\" (did you mean \"cell\"?)"},
      {"term on a surface the body lacks", kBase + term +
           "type = \"surface_pressure\"\nbody = \"cell\"\nsurface = \"outer\"\npressure = 10\n",
       "bad.toml:18: [term] surface = \"outer\": expected a surface of body \"cell\" (generator = \"block\")"},
      {"contact between a body and itself", kBase + term +
           "type = \"contact\"\nbodies = [\"cell\", \"cell\"]\nepsilon = 1e-20\ns0 = 1e-7\n",
       "bad.toml:17: [term] bodies = [\"cell\", \"cell\"]: expected different bodies (\"cell\" is named twice)"},
      {"contact cutoff inside the potential well", kBase + kLceBody + term +
           "type = \"contact\"\nbodies = [\"cell\", \"gel\"]\nepsilon = 1e-20\ns0 = 1e-7\ncutoff = 5e-8\n",
       "bad.toml:29: [term] cutoff = 5e-08: expected a cutoff larger than s0 = 1e-07 m"},
      {"wall contact exclusion inside the contact distance", kBase + term +
           "type = \"wall_contact\"\nbody = \"cell\"\nsurface = \"zmax\"\ndistance = 2e-7\npressure = 1e4\n"
           "exclusion = 1e-7\n",
       "bad.toml:21: [term] exclusion = 1e-07: expected an exclusion larger than distance = 2e-07 m (particles of one "
       "wall closer than the contact distance would repel at rest)"},
      // --- relaxation accelerators -----------------------------------------------------
      {"nested levels in a dynamic run", replaced(kBase, "t_end = 1.0\n", "t_end = 1.0\nnested_levels = [0.5]\n"),
       "bad.toml:5: [integrator] nested_levels = [0.5]: expected [] unless mode = \"relax\""},
      {"nested levels out of order",
       replaced(kBase, "t_end = 1.0\n", "mode = \"relax\"\nnested_levels = [0.5, 0.25]\n"),
       "bad.toml:5: [integrator] nested_levels = [0.5, 0.25]: expected factors in increasing order, coarsest first"},
      {"nested level not coarser", replaced(kBase, "t_end = 1.0\n", "mode = \"relax\"\nnested_levels = [1.0]\n"),
       "bad.toml:5: [integrator] nested_levels = [1]: expected"},
      {"mass scaling in a dynamic run", replaced(kBase, "t_end = 1.0\n", "t_end = 1.0\nmass_scaling = true\n"),
       "bad.toml:5: [integrator] mass_scaling = true: expected false unless mode = \"relax\""},
      {"contact mass scaling in a dynamic run",
       replaced(kBase, "t_end = 1.0\n", "t_end = 1.0\ncontact_mass_scaling = true\n"),
       "bad.toml:5: [integrator] contact_mass_scaling = true: expected false unless mode = \"relax\""},
      {"Newton-Krylov finish in a dynamic run",
       replaced(kBase, "t_end = 1.0\n", "t_end = 1.0\nrelax_finish = \"newton_krylov\"\n"),
       "bad.toml:5: [integrator] relax_finish = \"newton_krylov\": expected no relax_finish unless mode = \"relax\""},
      {"finish target without the finish",
       replaced(kBase, "t_end = 1.0\n", "mode = \"relax\"\nfinish_force_tol = 1e-9\n"),
       "bad.toml:5: [integrator] finish_force_tol = 1e-09: expected no finish_force_tol unless relax_finish = "
       "\"newton_krylov\""},
      {"finish step limit without the finish",
       replaced(kBase, "t_end = 1.0\n", "mode = \"relax\"\nfinish_max_newton_steps = 5\n"),
       "bad.toml:5: [integrator] finish_max_newton_steps = 5: expected no finish_max_newton_steps unless "
       "relax_finish = \"newton_krylov\""},
      {"unknown finish", replaced(kBase, "t_end = 1.0\n", "mode = \"relax\"\nrelax_finish = \"newton\"\n"),
       "bad.toml:5: [integrator] relax_finish = \"newton\": expected one of"},
      // --- values that keep arithmetic finite ----------------------------------------
      {"subnormal density", replaced(kBase, "name = \"cell\"\n", "name = \"cell\"\ndensity = 5e-324\n"),
       "bad.toml:7: [body] density = 5e-324: expected 0 or a number of at least 2.2e-308 in size"},
      {"subnormal item of a list", replaced(kBase, "size = [1, 1, 1]", "size = [1, 1e-310, 1]"),
       "bad.toml:9: [body.cloud] size = [1, 1e-310, 1]: expected 0 or a number of at least 2.2e-308 in size"},
      {"vtu cloud whose file does not exist",
       replaced(kBase, kBlockCloud, "generator = \"vtu\"\nfile = \"meshes/none.vtu\""),
       "bad.toml:9: [body.cloud] file = \"meshes/none.vtu\": expected an existing file (resolved to meshes/none.vtu)"},
  };
}

class MalformedScene : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedScene, ReportsFileLineKeyValueAndExpectation) {
  const Malformed& c = GetParam();
  try {
    parse_scene(c.toml, "bad.toml");
    FAIL() << "no error for: " << c.what;
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
        << c.what << "\n  message:  " << e.what() << "\n  expected: " << c.message;
    EXPECT_EQ(e.file(), "bad.toml");
  }
}

INSTANTIATE_TEST_SUITE_P(Table, MalformedScene, ::testing::ValuesIn(malformed_scenes()),
                         [](const ::testing::TestParamInfo<Malformed>& test) {
                           std::string name;
                           for (const char* p = test.param.what; *p; ++p) {
                             name += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
                           }
                           return name;
                         });

TEST(MalformedScene, TableHasAtLeastTwentyFiveCases) { EXPECT_GE(malformed_scenes().size(), 25u); }

// The base scene itself must be valid, or every case above would test nothing.
TEST(MalformedScene, BaseScenesAreValid) {
  EXPECT_NO_THROW(parse_scene(kBase, "ok.toml"));
  EXPECT_NO_THROW(parse_scene(kBase + kLceBody, "ok.toml"));
}

}  // namespace
}  // namespace rkpm::scene
