#include "cloud_checks.hpp"
#include "tet_mesh.hpp"

#include "rkpm/particles/generators.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace rkpm::particles {
namespace {

using testing::report;

BlockSpec jittered_block() {
  BlockSpec spec;
  spec.cells = {5, 4, 3};
  spec.size = Vec3(1.0, 0.8, 0.6);
  spec.jitter = 0.25;
  spec.seed = 3;
  return spec;
}

// Every interior facet appears in exactly two cells with bit-identical points and
// exactly opposite area vectors: what makes SCNI's smoothed gradients conserve.
void expect_facets_pair_exactly(const Cloud& cloud) {
  const DualCells cells(cloud);
  std::vector<DualFacet> facets;
  std::map<std::array<double, 3>, std::vector<Vec3>> by_point;
  std::size_t boundary_facets = 0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    cells.facets(i, facets);
    for (const DualFacet& f : facets) {
      if (f.on_boundary) {
        ++boundary_facets;
        continue;
      }
      by_point[{f.point.x(), f.point.y(), f.point.z()}].push_back(f.area);
    }
  }
  std::size_t unpaired = 0, mismatched = 0;
  for (const auto& [point, areas] : by_point) {
    if (areas.size() != 2) ++unpaired;
    else if (areas[0] != Vec3(-areas[1])) ++mismatched;
  }
  EXPECT_EQ(unpaired, 0u);
  EXPECT_EQ(mismatched, 0u);
  // Two triangles per boundary face corner.
  std::size_t corners = 0;
  for (const BoundaryFace& f : cloud.boundary_faces) corners += f.n_nodes;
  EXPECT_EQ(boundary_facets, 2 * corners);
}

TEST(DualCells, InteriorFacetsPairBitForBitOnHexes) {
  expect_facets_pair_exactly(make_block(jittered_block()));
  SphereSpec sphere;
  sphere.cells = 6;
  expect_facets_pair_exactly(make_sphere(sphere));
}

TEST(DualCells, InteriorFacetsPairBitForBitOnTets) { expect_facets_pair_exactly(testing::tet_block(jittered_block())); }

TEST(DualCells, InteriorFacetNormalsPointAwayFromTheParticle) {
  const Cloud cloud = make_block(jittered_block());
  const DualCells cells(cloud);
  std::vector<DualFacet> facets;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    cells.facets(i, facets);
    for (const DualFacet& f : facets) {
      // Boundary pieces contain the particle, so only interior facets can be tested this way.
      if (!f.on_boundary) {
        EXPECT_GT(f.area.dot(f.point - cloud.X[i]), 0.0) << "particle " << i;
      }
    }
  }
}

// Every boundary piece names the boundary face it lies on: a face of the owning
// particle, and the pieces of one face (from all its corners' cells) tile it, so
// their area vectors sum to the face's, (1/2) sum_k x_k x x_{k+1} (a property of
// the boundary loop alone). Interior facets name no face. Returns the worst
// relative mismatch of the sums.
double expect_boundary_pieces_tile_their_faces(const Cloud& cloud) {
  const DualCells cells(cloud);
  std::vector<DualFacet> facets;
  std::vector<Vec3> piece_sum(cloud.boundary_faces.size(), Vec3::Zero());
  std::size_t foreign = 0, bad_index = 0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    cells.facets(i, facets);
    for (const DualFacet& f : facets) {
      if (!f.on_boundary) {
        bad_index += f.face == -1 ? 0 : 1;
        continue;
      }
      if (f.face < 0 || f.face >= static_cast<std::int32_t>(cloud.boundary_faces.size())) {
        ++bad_index;
        continue;
      }
      const BoundaryFace& face = cloud.boundary_faces[f.face];
      foreign += std::count(face.nodes, face.nodes + face.n_nodes, i) == 1 ? 0 : 1;
      piece_sum[f.face] += f.area;
    }
  }
  EXPECT_EQ(bad_index, 0u);
  EXPECT_EQ(foreign, 0u);
  double worst = 0.0;
  for (std::size_t k = 0; k < cloud.boundary_faces.size(); ++k) {
    const BoundaryFace& face = cloud.boundary_faces[k];
    Vec3 exact = Vec3::Zero();
    for (int a = 0; a < face.n_nodes; ++a) exact += 0.5 * cloud.X[face.nodes[a]].cross(cloud.X[face.nodes[(a + 1) % face.n_nodes]]);
    worst = std::max(worst, (piece_sum[k] - exact).norm() / exact.norm());
  }
  EXPECT_LT(worst, 1e-12);
  return worst;
}

TEST(DualCells, BoundaryPiecesNameTheirFace) {
  report("block: max |sum of pieces - face area| / |face area|",
         expect_boundary_pieces_tile_their_faces(make_block(jittered_block())));
  report("tets: max |sum of pieces - face area| / |face area|",
         expect_boundary_pieces_tile_their_faces(testing::tet_block(jittered_block())));
  ShellSpec shell;
  shell.face_cells = 6;
  shell.layers = 3;
  report("shell: max |sum of pieces - face area| / |face area|",
         expect_boundary_pieces_tile_their_faces(make_shell(shell)));
}

// What the face is for: a particle on a block's edge or corner lies on two or
// three named surfaces, and each of its boundary pieces belongs to exactly one of
// them, the one whose outward axis its area vector points along.
TEST(DualCells, BoundaryPieceFaceSelectsTheNamedSurface) {
  const Cloud cloud = make_block(jittered_block());
  const DualCells cells(cloud);
  const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  std::vector<DualFacet> facets;
  std::size_t checked = 0, wrong = 0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    cells.facets(i, facets);
    for (const DualFacet& f : facets) {
      if (!f.on_boundary) continue;
      int axis = 0;
      f.area.cwiseAbs().maxCoeff(&axis);
      const std::string surface = names[axis][f.area[axis] > 0 ? 1 : 0];
      const BoundaryFace& face = cloud.boundary_faces[f.face];
      for (int a = 0; a < face.n_nodes; ++a) wrong += cloud.on_surface(face.nodes[a], surface) ? 0 : 1;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2u * 4u * 2u * (5 * 4 + 4 * 3 + 5 * 3));
  EXPECT_EQ(wrong, 0u);
}

TEST(DualCells, TetMeshVolumesAreaAndClosure) {
  const BlockSpec spec = jittered_block();
  const Cloud cloud = testing::tet_block(spec);
  EXPECT_EQ(cloud.mesh.n_elements(), 6 * 5 * 4 * 3);
  const double volume_error = testing::relative_error(testing::sum(cloud.volume), spec.size.prod());
  const double area_error = testing::relative_error(testing::boundary_area_sum(cloud), 2.0 * (0.8 + 0.48 + 0.6));
  report("tet block volume relative error", volume_error);
  report("tet block boundary area relative error", area_error);
  EXPECT_LT(volume_error, 1e-12);
  EXPECT_LT(area_error, 1e-12);
  EXPECT_EQ(cloud.boundary_faces.size(), 2u * 2u * (5 * 4 + 4 * 3 + 5 * 3));
  const auto closure = testing::closure_errors(cloud);
  report("tet closure: max |sum area| / sum |area|", closure.area_sum);
  report("tet closure: max |sum x area^T - V I| / V", closure.moment);
  EXPECT_LT(closure.area_sum, 1e-12);
  EXPECT_LT(closure.moment, 1e-12);
  // Same particles, same outer surface: the hex and tet duals agree in total.
  const Cloud hexes = make_block(spec);
  EXPECT_NEAR(testing::sum(cloud.volume), testing::sum(hexes.volume), 1e-13);
}

TEST(DualCells, VolumeMatchesFinalizedCloud) {
  const Cloud cloud = make_sphere(SphereSpec{});
  const DualCells cells(cloud);
  std::vector<DualFacet> scratch;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(cloud.size()); ++i) {
    EXPECT_EQ(cells.volume(i, scratch), cloud.volume[i]);
  }
}

TEST(FinalizeCloud, BoundaryFacesFaceOutward) {
  const Cloud cloud = make_sphere(SphereSpec{});
  for (const BoundaryFace& f : cloud.boundary_faces) {
    Vec3 c = Vec3::Zero(), n = Vec3::Zero();
    for (int k = 0; k < f.n_nodes; ++k) c += cloud.X[f.nodes[k]] / f.n_nodes;
    for (int k = 0; k < f.n_nodes; ++k) n += (cloud.X[f.nodes[k]] - c).cross(cloud.X[f.nodes[(k + 1) % f.n_nodes]] - c);
    EXPECT_GT(n.normalized().dot(c.normalized()), 0.9);  // centred unit sphere: normal ~ position
  }
}

Cloud two_cubes() {
  Cloud cloud;
  cloud.name = "two cubes";
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) cloud.X.emplace_back(i, j, k);
    }
  }
  auto id = [](int i, int j, int k) { return static_cast<std::int32_t>(i + 3 * (j + 2 * k)); };
  for (int i = 0; i < 2; ++i) {
    const std::int32_t n[8] = {id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
                               id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1)};
    cloud.mesh.add_element(ElementType::Hex8, n);
  }
  return cloud;
}

void expect_error(Cloud cloud, const std::string& fragment) {
  try {
    finalize_cloud(cloud);
    ADD_FAILURE() << "expected CloudError containing '" << fragment << "'";
  } catch (const CloudError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("two cubes"), std::string::npos) << e.what();
  }
}

TEST(FinalizeCloud, AcceptsAValidMesh) {
  Cloud cloud = two_cubes();
  finalize_cloud(cloud);
  EXPECT_NEAR(testing::sum(cloud.volume), 2.0, 1e-14);
  EXPECT_EQ(cloud.boundary_faces.size(), 10u);
  EXPECT_EQ(cloud.boundary_particles.size(), 12u);
  EXPECT_DOUBLE_EQ(cloud.volume[1], 0.25);  // middle node of the bottom edge row
}

TEST(FinalizeCloud, RejectsInvertedElement) {
  Cloud cloud = two_cubes();
  std::swap(cloud.mesh.nodes[8 + 0], cloud.mesh.nodes[8 + 4]);  // flip the second cube
  expect_error(cloud, "element 1 (Hex8) is inverted");
}

TEST(FinalizeCloud, RejectsUnusedParticle) {
  Cloud cloud = two_cubes();
  cloud.X.emplace_back(5, 5, 5);
  expect_error(cloud, "particle 12 belongs to no element");
}

TEST(FinalizeCloud, RejectsDuplicateParticles) {
  Cloud cloud = two_cubes();
  // A second copy of node 1 used by the second cube: the cubes no longer share a face.
  cloud.X.push_back(cloud.X[1]);
  for (int k = 8; k < 16; ++k) {
    if (cloud.mesh.nodes[k] == 1) cloud.mesh.nodes[k] = 12;
  }
  expect_error(cloud, "particles 1 and 12 coincide");
}

TEST(FinalizeCloud, RejectsParticlesWithinTheToleranceInEveryCoordinate) {
  Cloud cloud = two_cubes();
  // Off node 1 by 1e-9 in x, y and z: 1.7e-9 apart, within 1e-9 of the bounding-box
  // diagonal, but not equal in any coordinate the duplicate check sorts by.
  cloud.X.push_back(cloud.X[1] + Vec3(1e-9, -1e-9, 1e-9));
  for (int k = 8; k < 16; ++k) {
    if (cloud.mesh.nodes[k] == 1) cloud.mesh.nodes[k] = 12;
  }
  expect_error(cloud, "particles 1 and 12 coincide");
}

TEST(FinalizeCloud, RejectsOutOfRangeIds) {
  Cloud cloud = two_cubes();
  cloud.mesh.nodes[3] = 99;
  expect_error(cloud, "refers to particle 99");
}

}  // namespace
}  // namespace rkpm::particles
