#include "rkpm/sim/output.hpp"

#include <cmath>

namespace rkpm::sim {

namespace {

// Cauchy stress sigma = P F^T / J at one point, and its von Mises equivalent.
void stress_at(const Body& b, std::size_t L, double* sigma9, double& von_mises) {
  const Mat3& F = b.F[L];
  const Mat3 sigma = b.P[L] * F.transpose() / F.determinant();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) sigma9[3 * r + c] = sigma(r, c);
  const Mat3 sym = 0.5 * (sigma + sigma.transpose());
  const Mat3 dev = sym - sym.trace() / 3.0 * Mat3::Identity();
  von_mises = std::sqrt(1.5 * dev.squaredNorm());
}

}  // namespace

io::Frame make_frame(const World& world, CellOutput cells, std::vector<Vec3>& positions) {
  const std::size_t total = world.particle_count();
  bool any_director = false;
  for (const auto& b : world.bodies) any_director |= b->director.has_value();

  io::Frame frame;
  io::PointField displacement{"displacement", 3, {}}, velocity{"velocity", 3, {}}, body_id{"body_id", 1, {}},
      volume{"volume", 1, {}}, J{"J", 1, {}}, stress{"cauchy_stress", 9, {}}, von_mises{"von_mises", 1, {}},
      director{"director", 3, {}};
  for (auto* f : {&displacement, &velocity, &body_id, &volume, &J, &stress, &von_mises, &director})
    f->values.reserve(total * static_cast<std::size_t>(f->components));
  positions.clear();
  positions.reserve(total);

  std::vector<Vec3> u, w;
  std::int64_t offset = 0;
  for (const auto& bp : world.bodies) {
    const Body& b = *bp;
    physical_displacement(b, u);
    // Physical velocity: the same interpolation applied to the generalized velocities.
    w.resize(b.size());
    const auto& N = b.interpolation;
    for (std::size_t j = 0; j < b.size(); ++j) w[j] = rk::interpolate(N, b.v, static_cast<Index>(j));
    for (std::size_t i = 0; i < b.size(); ++i) {
      positions.push_back(b.cloud.X[i] + u[i]);
      displacement.values.insert(displacement.values.end(), u[i].data(), u[i].data() + 3);
      velocity.values.insert(velocity.values.end(), w[i].data(), w[i].data() + 3);
      body_id.values.push_back(b.id);
      volume.values.push_back(b.cloud.volume[i]);
      J.values.push_back(b.F[i].determinant());
      double s9[9], vm = 0.0;
      stress_at(b, i, s9, vm);
      stress.values.insert(stress.values.end(), s9, s9 + 9);
      von_mises.values.push_back(vm);
      const Vec3 h = b.director ? b.director->h[i] : Vec3::Zero();
      if (any_director) director.values.insert(director.values.end(), h.data(), h.data() + 3);
    }
    if (cells == CellOutput::Mesh) {
      const auto& mesh = b.cloud.mesh;
      for (int e = 0; e < mesh.n_elements(); ++e) {
        frame.cells.types.push_back(static_cast<std::uint8_t>(mesh.type[e]));
        for (int k = 0; k < mesh.element_size(e); ++k)
          frame.cells.connectivity.push_back(offset + mesh.element_nodes(e)[k]);
        frame.cells.offsets.push_back(static_cast<std::int64_t>(frame.cells.connectivity.size()));
      }
    }
    offset += static_cast<std::int64_t>(b.size());
  }
  if (cells == CellOutput::Points) frame.cells = io::vertex_cells(total);
  frame.points = &positions;
  frame.point_fields = {std::move(displacement), std::move(velocity), std::move(body_id), std::move(volume),
                        std::move(J), std::move(stress), std::move(von_mises)};
  if (any_director) frame.point_fields.push_back(std::move(director));
  return frame;
}

}  // namespace rkpm::sim
