// Shape of a cell at the end of the red-blood-cell relaxation (seed section 4.1),
// measured against the Evans-Fung profile of human red blood cells
// (VERIFICATION section 6):
//     T(r) = sqrt(1 - x^2) (0.81 + 7.83 x^2 - 4.39 x^4) um,  x = r / R0,  R0 = 3.91 um.
//
// The profile is read off the outer surface: its particles are split by the sign of
// their outward normal's axial component into a top and a bottom sheet, binned by
// distance r from the symmetry axis (z through the centroid), and the thickness is
// h(r) = top(r) - bottom(r).
//
// A shell with an inner surface (named "inner") also gets the same profile of that
// surface, split by the sign of the axial component of its normal pointing into the
// cavity: the gap between its top and bottom sheets is the thickness of the enclosed
// fluid. Only the surface's particles whose normal is within 60 deg of the axis enter
// (|n_z| >= |n| / 2): at the rim the inner surface turns vertical and its top and bottom
// meet, and there the split would measure no fluid at all. The smallest gap is taken
// per radial bin and angular sector, so a crossing on one side is not averaged away.
// Without the wall_contact term (src/terms/wall_contact/) nothing stops the two walls of
// one body from passing through each other; a negative gap flags such a shape as not
// physical (`walls_crossed`).
#pragma once

#include "rkpm/common/types.hpp"
#include "rkpm/particles/cloud.hpp"

#include <string>
#include <vector>

namespace rkpm::sim {

struct ShapeReport {
  std::vector<double> r;          // bin centres [m]
  std::vector<double> thickness;  // h(r) = top - bottom [m]
  std::vector<double> top, bottom;  // axial position of the sheets relative to the centroid [m]
  std::vector<double> evans_fung; // Evans-Fung thickness scaled to the same diameter [m]
  double diameter = 0.0;          // D = 2 max r over the outer surface [m]
  double h_min = 0.0;             // thickness at the centre [m]
  double h_max = 0.0;             // largest thickness [m]
  double r_hmax_over_R = 0.0;     // where h_max sits, relative to D/2
  double updown_asymmetry = 0.0;  // max |top + bottom| / h_max: 0 when mirror-symmetric (a cup is not)
  double axial_asymmetry = 0.0;   // max deviation of the sector profiles from the mean / h_max
  double volume = 0.0;            // enclosed by the outer surface [m^3]
  double area = 0.0;              // of the outer surface [m^2]
  double reduced_volume = 0.0;    // V / (4 pi / 3 (A / 4 pi)^(3/2)); Evans-Fung: 0.644
  double rms_vs_evans_fung = 0.0; // RMS of h - T_EF over the bins, as a fraction of D
  // Inner surface (shells only; empty / zero otherwise), on the bins of `r`:
  std::vector<double> inner_top, inner_bottom;  // axial position of its sheets [m]
  std::vector<char> inner_in_bin;  // 1 where the bin holds both inner sheets
  bool has_inner_surface = false;
  bool has_inner_gap = false;            // some bin holds both inner sheets
  double inner_gap_centre = 0.0;         // fluid thickness in the innermost bin with both sheets [m]
  double inner_gap_min = 0.0;            // smallest fluid thickness over the bins and sectors [m]
  double wall_thickness_centre = 0.0;    // there: mean of the top and bottom wall's thickness [m]
  bool walls_crossed = false;            // inner_gap_min < -0.01 h_max
  bool biconcave = false;         // h_min / h_max <= 0.5, r(h_max)/R in [0.55, 0.85], walls not crossed
  // The red-blood-cell scene's four criteria together (examples/rbc/README.md): biconcave,
  // and the profile within 5 % of D of Evans-Fung (RMS) and up-down symmetric to 5 % of h_max.
  bool matches_evans_fung = false;
};

// `positions`: current (physical) positions of all particles of the cloud; the outer
// surface is the named surface `surface` of the cloud (its boundary faces); the
// surface named `inner`, if the cloud has one, gives the fluid gap.
ShapeReport measure_shape(const particles::Cloud& cloud, const std::vector<Vec3>& positions,
                          const std::string& surface, int bins = 32, const std::string& inner = "inner");

// Evans-Fung thickness [m] at radius r for a cell of diameter D (the profile scaled).
double evans_fung_thickness(double r, double diameter);

// Enclosed volume and area of the closed surface made of the faces on `surface`.
void surface_volume_area(const particles::Cloud& cloud, const std::vector<Vec3>& positions,
                         const std::string& surface, double& volume, double& area);

}  // namespace rkpm::sim
