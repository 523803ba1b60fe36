// Gmsh input (Gmsh's C++ API): .geo files meshed with a declared size, hand-written
// .msh files, second-order elements reduced to their corners, physical surfaces as
// named surfaces, and the files it must refuse with the file and element named.
#include "rkpm/particles/generators.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>

namespace rkpm::particles {
namespace {

namespace fs = std::filesystem;

std::string write_file(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(::testing::TempDir()) / "rkpm_particles_gmsh";
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

double total_volume(const Cloud& c) { return std::accumulate(c.volume.begin(), c.volume.end(), 0.0); }

// A 2 x 1 x 1 box meshed as 2 x 2 x 2 hexahedra (transfinite, recombined).
const std::string kHexBox = R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
Physical Surface("xmin") = Surface In BoundingBox{-0.01, -0.01, -0.01, 0.01, 1.01, 1.01};
)";

// The same box as tetrahedra; `order` 1 or 2.
std::string tet_box(int order) {
  return "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\nMesh.ElementOrder = " + std::to_string(order) +
         ";\nPhysical Surface(\"bottom\") = Surface In BoundingBox{-0.01, -0.01, -0.01, 2.01, 1.01, 0.01};\n";
}

// The same box with no option of its own, as an untrusted script may be.
std::string tet_box_untrusted() { return "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n"; }

// Two positively oriented tetrahedra sharing the face (2, 3, 4), format 2.2, with the
// triangle (1, 2, 3) in the physical surface "base"; `tets` replaces their element lines.
std::string two_tets(const std::string& tets = "2 4 2 2 1 1 2 3 4\n3 4 2 2 1 2 3 4 5\n") {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n2 1 \"base\"\n3 2 \"solid\"\n$EndPhysicalNames\n"
         "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n$EndNodes\n$Elements\n3\n"
         "1 2 2 1 1 1 2 3\n" + tets + "$EndElements\n";
}

TEST(ImportGmsh, AHexahedralGeoBecomesHexahedraWithItsPhysicalSurface) {
  // Transfinite meshing is refused in an untrusted script: this one is the test's own.
  const Cloud c = import_gmsh({write_file("hex.geo", kHexBox), 1e-6, 1.0, true});
  ASSERT_EQ(c.size(), 27u);
  EXPECT_EQ(c.mesh.n_elements(), 8);
  for (int e = 0; e < c.mesh.n_elements(); ++e) EXPECT_EQ(c.mesh.type[e], ElementType::Hex8);
  EXPECT_NEAR(total_volume(c), 2e-18, 1e-30) << "scale 1e-6 applies to the coordinates";
  ASSERT_EQ(c.surface_names, (std::vector<std::string>{"surface", "xmin"}));
  int on_xmin = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const bool at_x0 = std::abs(c.X[i].x()) < 1e-15;
    EXPECT_EQ(c.on_surface(static_cast<std::int32_t>(i), "xmin"), at_x0) << i;
    on_xmin += at_x0;
  }
  EXPECT_EQ(on_xmin, 9);
  EXPECT_EQ(c.boundary_particles.size(), 26u);
  for (auto p : c.boundary_particles) EXPECT_TRUE(c.on_surface(p, "surface"));
}

TEST(ImportGmsh, SecondOrderTetrahedraKeepOnlyTheirCorners) {
  // Mesh.ElementOrder is refused in an untrusted script: these are the test's own.
  const Cloud first = import_gmsh({write_file("tet1.geo", tet_box(1)), 1.0, 0.5, true});
  const Cloud second = import_gmsh({write_file("tet2.geo", tet_box(2)), 1.0, 0.5, true});
  EXPECT_EQ(second.size(), first.size()) << "the mid-edge nodes of a second-order mesh are not particles";
  EXPECT_EQ(second.mesh.n_elements(), first.mesh.n_elements());
  EXPECT_GT(first.size(), 50u);
  EXPECT_NEAR(total_volume(second), 2.0, 1e-12);
  int bottom = 0;
  for (auto p : second.boundary_particles) {
    const bool at_z0 = std::abs(second.X[p].z()) < 1e-12;
    EXPECT_EQ(second.on_surface(p, "bottom"), at_z0) << p;
    bottom += at_z0;
  }
  EXPECT_GT(bottom, 10);
}

TEST(ImportGmsh, AHandWrittenMshKeepsItsNodesAndNamedSurface) {
  const Cloud c = import_gmsh({write_file("two_tets.msh", two_tets()), 1.0, 0.0});
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c.mesh.n_elements(), 2);
  EXPECT_NEAR(total_volume(c), 1.0 / 6.0 + 2.0 / 6.0, 1e-14);
  ASSERT_EQ(c.surface_names, (std::vector<std::string>{"surface", "base"}));
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_EQ(c.on_surface(static_cast<std::int32_t>(i), "base"), std::abs(c.X[i].z()) < 1e-15 && c.X[i].sum() < 1.5)
        << i;
  EXPECT_EQ(gmsh_surface_names(write_file("names.msh", two_tets())), (std::vector<std::string>{"surface", "base"}));
  EXPECT_EQ(gmsh_particle_estimate({write_file("count.msh", two_tets()), 1.0, 0.0}), 5.0);
}

void expect_refused(const GmshImportSpec& spec, const std::vector<std::string>& parts) {
  try {
    import_gmsh(spec);
    FAIL() << "accepted " << spec.path;
  } catch (const CloudError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Gmsh file '" + spec.path + "'"), std::string::npos) << what;
    for (const auto& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

TEST(ImportGmsh, BadFilesAreRefusedNamingTheFileAndElement) {
  // Element 3 with two nodes swapped: negative volume.
  expect_refused({write_file("inverted.msh", two_tets("2 4 2 2 1 1 2 3 4\n3 4 2 2 1 3 2 4 5\n")), 1.0, 0.0},
                 {"1 of 2 volume elements are inverted or degenerate (first: element 3)"});
  // A flat tetrahedron: four nodes in one plane.
  expect_refused({write_file("flat.msh", two_tets("2 4 2 2 1 1 2 3 4\n3 4 2 2 1 1 2 3 3\n")), 1.0, 0.0},
                 {"inverted or degenerate (first: element 3)"});
  // A prism (Gmsh type 6).
  expect_refused({write_file("prism.msh", two_tets("2 4 2 2 1 1 2 3 4\n3 6 2 2 1 1 2 3 4 5 5\n")), 1.0, 0.0},
                 {"element 3 is a Prism 6", "only tetrahedra and hexahedra"});
  expect_refused({write_file("text.msh", "this is not a mesh\n"), 1.0, 0.0}, {"expected a Gmsh mesh"});
  expect_refused({write_file("surface_only.msh",
                             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                             "$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n"),
                  1.0, 0.0},
                 {"has no volume elements"});
  std::string nan_node = two_tets();
  nan_node.replace(nan_node.find("5 1 1 1"), 7, "5 1 nan 1");
  expect_refused({write_file("nan.msh", nan_node), 1.0, 0.0}, {"node 5 has a coordinate that is not a finite number"});
  expect_refused({write_file("no_size.geo", tet_box(1)), 1.0, 0.0, true}, {"a .geo file needs a mesh size"});
}

// Scripts that define no entity make Gmsh throw a std::string from its bounding box and
// meshing calls: each use of the API turns it into a CloudError naming the file.
TEST(ImportGmsh, AGeoWithoutEntitiesIsRefusedNotACrash) {
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"empty.geo", ""},
           {"comment.geo", "// nothing but a comment\n"},
           {"nothing_left.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
                                "Box(2) = {-1, -1, -1, 3, 3, 3};\n"
                                "BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };\n"}}) {
    const std::string path = write_file(name, text);
    EXPECT_THROW(gmsh_particle_estimate({path, 1.0, 0.5}), CloudError) << name;
    expect_refused({path, 1.0, 0.5}, {});
  }
}

// An untrusted .geo is screened before Gmsh runs it: commands that act outside the
// geometry are refused naming the file, the line and what was refused, including the
// spellings that reach a command without its plain name; the same words in comments and
// strings, numbers with a point, and a trusted file pass the screen. Scripts that would
// end the process or run a command are checked by the screen alone, so that a
// regression fails the test instead of ending it.
TEST(ImportGmsh, AnUntrustedGeoThatActsOutsideItsGeometryIsRefused) {
  const std::string box = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n";
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"SystemCall \"touch pwned\";\n", "line 3: 'SystemCall'"},
      {"System \"touch pwned\";\n", "line 3: 'System'"},
      {"S2N[\"SystemCall\"] \"touch pwned\";\n", "line 3: 'S2N'"},
      {"Exit;\n", "line 3: 'Exit'"},
      {"For i In {1:1000000000}\nEndFor\n", "line 3: 'For'"},
      {"While (1)\nEndWhile\n", "line 3: 'While'"},
      {"Mesh.MeshSizeFactor = 1e-3;\n", "line 3: 'Mesh'"},
      {"Geometry.Tolerance = 1;\n", "line 3: an option"},
      {"General .AbortOnError = 4;\n", "line 3: an option"},
      {"General[0].AbortOnError = 4;\n", "line 3: an option"},
      {"Delete Options;\n", "line 3: 'Options'"},
      {"Sleep.3e3;\n", "line 3: 'Sleep'"},
      {"Include \"other.geo\";\n", "line 3: 'Include'"},
      {"/* a\nlong comment */ Sleep 100;\n", "line 4: 'Sleep'"},
      // Gmsh's strings have no escapes and two kinds of quotes: nothing hides in them.
      {"a = '//'; System \"x\";\n", "line 3: 'System'"},
      {"a = '\"'; System 'x'; b = '\"';\n", "line 3: 'System'"},
      {"a = \"\\\"; SystemCall \"x\"; b = \"\\\";\n", "line 3: 'SystemCall'"},
      {std::string("// a comment\0 Exit;\n", 19), "line 3: a NUL byte"},
  };
  for (const auto& [command, message] : refused) {
    const std::string path = write_file("untrusted.geo", box + command);
    try {
      screen_geo_script(path);
      ADD_FAILURE() << "accepted: " << command;
    } catch (const CloudError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("Gmsh file '" + path + "' " + message), std::string::npos) << what;
      EXPECT_NE(what.find("trusted = true"), std::string::npos) << what;
    }
  }
  // The import screens too (a script that, unscreened, would only loop on a number).
  expect_refused({write_file("loops.geo", box + "For i In {1:3}\nEndFor\n"), 1.0, 0.5}, {"line 3: 'For'"});

  const std::string harmless = write_file("harmless.geo", box + "// SystemCall \"x\"; Exit;\n"
                                                                  "Printed = 1.5e-3 + .5; // a name like one\n"
                                                                  "Physical Surface('Exit') = {1};\n");
  EXPECT_NO_THROW(screen_geo_script(harmless));
  EXPECT_EQ(import_gmsh({harmless, 1.0, 0.5}).surface_names, (std::vector<std::string>{"surface", "Exit"}));
  EXPECT_NO_THROW(screen_geo_script(std::string(RKPM_SOURCE_DIR) + "/examples/spread_cell/spread_cell.geo"));
  // A trusted script runs as written (Mesh.ElementOrder here), and leaves nothing behind:
  // the next untrusted import meshes at first order again.
  const Cloud second_order = import_gmsh({write_file("trusted.geo", tet_box(2)), 1.0, 0.5, true});
  const Cloud after = import_gmsh({write_file("plain.geo", box), 1.0, 0.5});
  for (int e = 0; e < after.mesh.n_elements(); ++e) EXPECT_EQ(after.mesh.type[e], ElementType::Tet4);
  EXPECT_GT(second_order.size(), 0u);
}

// Gmsh runs any file whose first line is not a mesh header as a script, whatever its
// name: an untrusted file that is not a .geo must start as a mesh does.
TEST(ImportGmsh, AnUntrustedScriptUnderAMeshNameIsRefused) {
  const std::string path = write_file("script.msh", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n");
  expect_refused({path, 1.0, 0.0}, {"expected a Gmsh mesh, whose first line is $MeshFormat"});
  EXPECT_THROW(gmsh_surface_names(path), CloudError);
  EXPECT_THROW(gmsh_particle_estimate({path, 1.0, 0.0}), CloudError);
}

// A slab far thinner than the mesh size still gets a layer of elements through it: the
// estimate counts at least one cell per extent, and bounds what the mesher makes.
TEST(ImportGmsh, TheGeoEstimateBoundsAThinSlab) {
  const std::string path =
      write_file("slab.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 10, 10, 0.01};\n");
  const double estimate = gmsh_particle_estimate({path, 1.0, 0.5});
  const Cloud c = import_gmsh({path, 1.0, 0.5});
  EXPECT_GE(estimate, static_cast<double>(c.size())) << "the pre-flight under-counted the mesh";
  EXPECT_LT(estimate, 20.0 * static_cast<double>(c.size())) << "the estimate is no longer a bound worth the name";
}

// Gmsh runs in a child process: a file that crashes Gmsh's reader (found by fuzz_msh)
// is refused naming the file, and a file it stopped reading, which in one process left
// Gmsh's state broken (every later .geo read as empty), does not spoil the next import.
TEST(ImportGmsh, AFileThatCrashesGmshIsRefusedNamingTheFile) {
  const std::string path = RKPM_SOURCE_DIR "/tests/fuzz/corpus/msh/regression-gmsh-crash-2.msh";
  expect_refused({path, 1.0, 0.0}, {"Gmsh crashed (", "expected a valid Gmsh file"});
}

TEST(ImportGmsh, AFileGmshStoppedReadingDoesNotSpoilTheNext) {
  expect_refused({write_file("wrong_node.msh", two_tets("2 4 2 2 1 1 2 3 4\n3 4 2 2 1 2 3 4 9\n")), 1.0, 0.0},
                 {"Wrong node index 9"});
  const Cloud c = import_gmsh({write_file("after.geo", tet_box_untrusted()), 1.0, 0.5});
  EXPECT_GT(c.size(), 8u);
  EXPECT_NEAR(total_volume(c), 2.0, 1e-9);
}

}  // namespace
}  // namespace rkpm::particles
