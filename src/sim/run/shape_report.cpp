#include "rkpm/sim/shape_report.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rkpm::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kSectors = 8;

bool face_on(const particles::Cloud& cloud, const particles::BoundaryFace& face, std::uint32_t bit) {
  for (int k = 0; k < face.n_nodes; ++k)
    if (!(cloud.surface_mask[face.nodes[k]] & bit)) return false;
  return true;
}
}  // namespace

double evans_fung_thickness(double r, double diameter) {
  // Evans & Fung (1972): R0 = 3.91 um; lengths scale with D / 7.82 um.
  const double x = std::min(1.0, 2.0 * r / diameter);
  const double um = diameter / 7.82;
  return std::sqrt(1.0 - x * x) * (0.81 + 7.83 * x * x - 4.39 * x * x * x * x) * um;
}

void surface_volume_area(const particles::Cloud& cloud, const std::vector<Vec3>& positions,
                         const std::string& surface, double& volume, double& area) {
  const std::uint32_t bit = cloud.surface_bit(surface);
  if (bit == 0u) throw std::invalid_argument("shape report: the cloud has no surface named '" + surface + "'");
  volume = 0.0;
  area = 0.0;
  for (const auto& face : cloud.boundary_faces) {
    if (!face_on(cloud, face, bit)) continue;
    // Fan triangulation from the first node; outward orientation as stored.
    for (int k = 1; k + 1 < face.n_nodes; ++k) {
      const Vec3& a = positions[face.nodes[0]];
      const Vec3& b = positions[face.nodes[k]];
      const Vec3& c = positions[face.nodes[k + 1]];
      volume += a.dot(b.cross(c)) / 6.0;
      area += 0.5 * (b - a).cross(c - a).norm();
    }
  }
}

namespace {

// Current normals of a surface's particles (sums of area-weighted face normals,
// outward from the solid as the faces are stored) and which particles are on it.
void surface_normals(const particles::Cloud& cloud, const std::vector<Vec3>& positions, std::uint32_t bit,
                     std::vector<Vec3>& normal, std::vector<char>& on) {
  normal.assign(cloud.size(), Vec3::Zero());
  on.assign(cloud.size(), 0);
  for (const auto& face : cloud.boundary_faces) {
    if (!face_on(cloud, face, bit)) continue;
    const Vec3& p0 = positions[face.nodes[0]];
    const Vec3 a = face.n_nodes == 3
                       ? Vec3(0.5 * (positions[face.nodes[1]] - p0).cross(positions[face.nodes[2]] - p0))
                       : Vec3(0.5 * (positions[face.nodes[2]] - p0).cross(positions[face.nodes[3]] - positions[face.nodes[1]]));
    for (int k = 0; k < face.n_nodes; ++k) {
      normal[face.nodes[k]] += a;
      on[face.nodes[k]] = 1;
    }
  }
}

// Sums of the axial position per (radial bin, sector) for the top and the bottom sheet
// of one surface. `top_sign` = +1: a particle whose normal points up is on the top
// sheet (outer surface); -1: pointing down (inner surface, whose normal points into
// the cavity).
struct SheetBins {
  std::vector<double> top_sum, bot_sum;
  std::vector<int> top_n, bot_n;
  // Mean axial position of each sheet over the sectors of bin b; false if a sheet is empty.
  bool bin(int b, double& top, double& bottom) const {
    double ts = 0, bs = 0;
    int tn = 0, bn = 0;
    for (int k = b * kSectors; k < (b + 1) * kSectors; ++k) {
      ts += top_sum[k];
      tn += top_n[k];
      bs += bot_sum[k];
      bn += bot_n[k];
    }
    if (tn == 0 || bn == 0) return false;
    top = ts / tn;
    bottom = bs / bn;
    return true;
  }
};

// `min_axial`: particles whose |n_z| is below this fraction of |n| are left out.
SheetBins bin_sheets(const std::vector<Vec3>& positions, const std::vector<Vec3>& normal,
                     const std::vector<char>& on, double top_sign, const Vec3& centre, double R, int nb,
                     double min_axial = 0.0) {
  SheetBins s{std::vector<double>(nb * kSectors, 0.0), std::vector<double>(nb * kSectors, 0.0),
              std::vector<int>(nb * kSectors, 0), std::vector<int>(nb * kSectors, 0)};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!on[i] || std::abs(normal[i].z()) < min_axial * normal[i].norm()) continue;
    const Vec3 p = positions[i] - centre;
    const double r = std::hypot(p.x(), p.y());
    const int b = std::min(nb - 1, static_cast<int>(r / R * nb));
    const double angle = std::atan2(p.y(), p.x()) + kPi;
    const int sector = std::min(kSectors - 1, static_cast<int>(angle / (2.0 * kPi) * kSectors));
    const int k = b * kSectors + sector;
    // A normal horizontal to round-off marks the fold where the sheets meet (the equator
    // of a mirror-symmetric shape), on neither sheet: a tie given to one sheet would
    // make a symmetric shape look up-down asymmetric in the outermost bin.
    const double up = top_sign * normal[i].z();
    if (std::abs(up) <= 1e-9 * normal[i].norm()) continue;
    if (up > 0.0) {
      s.top_sum[k] += p.z();
      ++s.top_n[k];
    } else {
      s.bot_sum[k] += p.z();
      ++s.bot_n[k];
    }
  }
  return s;
}

}  // namespace

ShapeReport measure_shape(const particles::Cloud& cloud, const std::vector<Vec3>& positions,
                          const std::string& surface, int bins, const std::string& inner) {
  const std::uint32_t bit = cloud.surface_bit(surface);
  if (bit == 0u) throw std::invalid_argument("shape report: the cloud has no surface named '" + surface + "'");
  ShapeReport s;
  surface_volume_area(cloud, positions, surface, s.volume, s.area);
  s.reduced_volume = s.volume / (4.0 * kPi / 3.0 * std::pow(s.area / (4.0 * kPi), 1.5));

  std::vector<Vec3> normal;
  std::vector<char> on;
  surface_normals(cloud, positions, bit, normal, on);
  Vec3 centre = Vec3::Zero();
  int count = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (on[i]) {
      centre += positions[i];
      ++count;
    }
  centre /= count;
  double R = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (on[i]) R = std::max(R, std::hypot(positions[i].x() - centre.x(), positions[i].y() - centre.y()));
  s.diameter = 2.0 * R;

  const int nb = bins;
  const SheetBins outer = bin_sheets(positions, normal, on, +1.0, centre, R, nb);
  SheetBins inner_bins;
  const std::uint32_t inner_bit = inner.empty() ? 0u : cloud.surface_bit(inner);
  s.has_inner_surface = inner_bit != 0u;
  if (s.has_inner_surface) {
    std::vector<Vec3> inner_normal;
    std::vector<char> inner_on;
    surface_normals(cloud, positions, inner_bit, inner_normal, inner_on);
    inner_bins = bin_sheets(positions, inner_normal, inner_on, -1.0, centre, R, nb, 0.5);
  }

  double rms = 0.0;
  int rms_n = 0;
  for (int b = 0; b < nb; ++b) {
    double top = 0.0, bottom = 0.0;
    if (!outer.bin(b, top, bottom)) continue;
    const double r = (b + 0.5) * R / nb;
    s.r.push_back(r);
    s.top.push_back(top);
    s.bottom.push_back(bottom);
    s.thickness.push_back(top - bottom);
    s.evans_fung.push_back(evans_fung_thickness(r, s.diameter));
    rms += std::pow(s.thickness.back() - s.evans_fung.back(), 2);
    ++rms_n;
    double inner_top = 0.0, inner_bottom = 0.0;
    const bool in_bin = s.has_inner_surface && inner_bins.bin(b, inner_top, inner_bottom);
    s.inner_in_bin.push_back(in_bin ? 1 : 0);
    s.inner_top.push_back(in_bin ? inner_top : 0.0);
    s.inner_bottom.push_back(in_bin ? inner_bottom : 0.0);
    if (!in_bin) continue;
    if (!s.has_inner_gap) {
      s.has_inner_gap = true;
      s.inner_gap_centre = inner_top - inner_bottom;
      s.inner_gap_min = s.inner_gap_centre;
      s.wall_thickness_centre = 0.5 * ((top - inner_top) + (inner_bottom - bottom));
    }
    // Per sector: a crossing on one side of the cell shows.
    for (int k = b * kSectors; k < (b + 1) * kSectors; ++k)
      if (inner_bins.top_n[k] > 0 && inner_bins.bot_n[k] > 0)
        s.inner_gap_min = std::min(s.inner_gap_min, inner_bins.top_sum[k] / inner_bins.top_n[k] -
                                                        inner_bins.bot_sum[k] / inner_bins.bot_n[k]);
  }
  if (s.thickness.empty()) throw std::runtime_error("shape report: no part of the surface has both a top and a bottom");
  s.rms_vs_evans_fung = std::sqrt(rms / rms_n) / s.diameter;
  s.h_min = s.thickness.front();
  const auto it = std::max_element(s.thickness.begin(), s.thickness.end());
  s.h_max = *it;
  s.r_hmax_over_R = s.r[static_cast<std::size_t>(it - s.thickness.begin())] / R;
  // A margin of 1 % of h_max (30 nm in the seed's cell) keeps sector noise of a sheet
  // that touches but has not crossed from counting.
  s.walls_crossed = s.has_inner_gap && s.inner_gap_min < -0.01 * s.h_max;
  for (std::size_t j = 0; j < s.r.size(); ++j)
    s.updown_asymmetry = std::max(s.updown_asymmetry, std::abs(s.top[j] + s.bottom[j]) / s.h_max);
  // Axial asymmetry: each sector's thickness against the mean, over the bins all sectors see.
  for (int b = 0; b < nb; ++b) {
    const double r = (b + 0.5) * R / nb;
    const auto j = std::find(s.r.begin(), s.r.end(), r);
    if (j == s.r.end()) continue;
    const double mean = s.thickness[static_cast<std::size_t>(j - s.r.begin())];
    for (int k = b * kSectors; k < (b + 1) * kSectors; ++k) {
      if (outer.top_n[k] == 0 || outer.bot_n[k] == 0) continue;
      s.axial_asymmetry = std::max(s.axial_asymmetry, std::abs(outer.top_sum[k] / outer.top_n[k] -
                                                               outer.bot_sum[k] / outer.bot_n[k] - mean) / s.h_max);
    }
  }
  s.biconcave = s.h_min / s.h_max <= 0.5 && s.r_hmax_over_R >= 0.55 && s.r_hmax_over_R <= 0.85 && !s.walls_crossed;
  s.matches_evans_fung = s.biconcave && s.rms_vs_evans_fung <= 0.05 && s.updown_asymmetry <= 0.05;
  return s;
}

}  // namespace rkpm::sim
