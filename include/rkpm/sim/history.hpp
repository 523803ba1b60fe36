// history.csv: one row per frame with the quantities a user follows over a run —
// energies and their balance, the relaxation residual, enclosed volumes and, for
// the body named by [output] shape_report, its volume, area, reduced volume, h_min/h_max
// and the smallest fluid gap between its faces (sim/shape_report.hpp).
#pragma once

#include "rkpm/sim/integrator.hpp"
#include "rkpm/sim/shape_report.hpp"
#include "rkpm/sim/world.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rkpm::io {
class Json;
}

namespace rkpm::sim {

class History {
 public:
  // `shape_body` may be null. When resuming, keeps the rows up to the restored step (a
  // killed run may have written more, and half a row) and appends.
  // On a distributed run every rank records (the measures are collective) and rank 0
  // alone opens and writes the file.
  History(const std::filesystem::path& path, const World& world, const Body* shape_body, bool resume);
  void record(const World& world, Integrator& integrator);

 private:
  // Throws io::NonFiniteValue naming the first column of `row` that is not finite.
  void refuse_non_finite(const std::string& row) const;

  bool writes_ = true;
  std::vector<std::string> columns_;
  std::filesystem::path path_;
  std::ofstream out_;
  const Body* shape_body_;
};

// The final shape of `body`'s outer surface: summary entries and shape_profile.csv.
// Distributed: collective, every rank gets the report.
ShapeReport final_shape(const Body& body, const par::Comm& comm = par::Comm::self());
// The summary's "shape" entries of a report.
io::Json shape_entries(const ShapeReport& shape);
void write_shape(const ShapeReport& shape, const std::filesystem::path& profile_csv, io::Json& summary);

}  // namespace rkpm::sim
