// Settings of the contact term, read from its [[term]] table (params.cpp).
#pragma once

#include "rkpm/scene/settings_table.hpp"

#include <array>
#include <string>
#include <vector>

namespace rkpm::sim {

enum class StiffnessLaw { none, linear };
// pairs: seed Eq. 14 by nodal quadrature over both volumes (contact.hpp); surface: its
// depth integrals in closed form, over the first body's surface (surface_contact.hpp).
enum class ContactFormulation { pairs, surface };

struct ContactSettings {
  std::vector<std::string> bodies;      // the two bodies, by name (the term acts between them)
  double epsilon = 0.0;                 // eps [J]
  double s0 = 0.0;                      // sigma0 [m]
  double cutoff = 0.0;                  // [m]
  double skin = 0.0;                    // [m]
  std::array<double, 2> beta = {0.0, 0.0};  // molecules per reference volume [1/m^3]; 0: particles / volume
  StiffnessLaw law = StiffnessLaw::none;
  std::string substrate;                // the body (by name) whose stiffness sets eps under the linear law
  double stiffness_reference = 0.0;     // mu_ref [Pa]; 0: volume-weighted mean over the substrate
  std::string report_surface;           // surface of body B for the gap report (contact_report.hpp); empty: none
  double contact_gap = 0.0;             // patch threshold of the report [m]; 0: s0
  ContactFormulation formulation = ContactFormulation::pairs;
};

}  // namespace rkpm::sim

namespace rkpm::terms::contact {
const scene::SettingsTable<sim::ContactSettings>& settings_table();
}  // namespace rkpm::terms::contact
