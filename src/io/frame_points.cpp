#include "rkpm/io/frame_points.hpp"

#include "rkpm/io/pvd_series.hpp"

#include <fmt/format.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace rkpm::io {

namespace {

template <class Reader>
vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::filesystem::path& path, const char* kind) {
  vtkNew<Reader> reader;
  if (!reader->CanReadFile(path.string().c_str()))
    throw std::runtime_error(fmt::format("{}: not a VTK XML {} file", path.string(), kind));
  reader->SetFileName(path.string().c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0) throw std::runtime_error(fmt::format("{}: VTK could not read it", path.string()));
  return reader->GetOutput();
}

std::vector<std::int64_t> integer_field(vtkUnstructuredGrid* grid, const char* name) {
  std::vector<std::int64_t> values;
  vtkDataArray* array = grid->GetPointData()->GetArray(name);
  if (array == nullptr) return values;
  values.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    values[static_cast<std::size_t>(t)] = static_cast<std::int64_t>(std::llround(array->GetComponent(t, 0)));
  return values;
}

}  // namespace

FramePoints read_frame_points(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error(path.string() + ": no such file (expected a .vtu or .pvtu frame written by rkpm run)");
  const bool parallel = path.extension() == ".pvtu";
  const auto grid = parallel ? read_grid<vtkXMLPUnstructuredGridReader>(path, "parallel unstructured-grid (.pvtu)")
                             : read_grid<vtkXMLUnstructuredGridReader>(path, "unstructured-grid (.vtu)");
  vtkPoints* points = grid->GetPoints();
  if (points == nullptr || points->GetNumberOfPoints() == 0)
    throw std::runtime_error(path.string() + ": VTK read no points from it (expected a frame with particles)");
  const auto n = static_cast<std::size_t>(points->GetNumberOfPoints());
  vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
  std::vector<std::int64_t> body = integer_field(grid, "body_id");
  std::vector<std::int64_t> id = integer_field(grid, "particle_id");
  if (body.empty() || id.empty()) {  // file order: one body, each point once
    body.assign(n, 0);
    id.resize(n);
    for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::int64_t>(i);
  }

  FramePoints out;
  for (std::size_t i = 0; i < n; ++i) {
    if (body[i] < 0 || id[i] < 0)
      throw std::runtime_error(fmt::format("{}: point {} has body_id {} and particle_id {} (expected both >= 0)",
                                           path.string(), i, body[i], id[i]));
    const auto b = static_cast<std::size_t>(body[i]);
    if (out.body_size.size() <= b) out.body_size.resize(b + 1, 0);
    out.body_size[b] = std::max(out.body_size[b], static_cast<std::size_t>(id[i]) + 1);
  }
  std::vector<std::size_t> first(out.body_size.size() + 1, 0);
  for (std::size_t b = 0; b < out.body_size.size(); ++b) first[b + 1] = first[b] + out.body_size[b];
  const std::size_t total = first.back();
  out.position.assign(total, Vec3::Constant(std::nan("")));
  if (u != nullptr) out.displacement.assign(total, Vec3::Zero());
  std::vector<char> seen(total, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = first[static_cast<std::size_t>(body[i])] + static_cast<std::size_t>(id[i]);
    double x[3];
    points->GetPoint(static_cast<vtkIdType>(i), x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw std::runtime_error(fmt::format("{}: point {} is not finite", path.string(), i));
    out.position[k] = Vec3(x[0], x[1], x[2]);  // a halo copy holds the owner's value
    if (u != nullptr) out.displacement[k] = Vec3(u->GetComponent(i, 0), u->GetComponent(i, 1), u->GetComponent(i, 2));
    seen[k] = 1;
  }
  for (std::size_t b = 0; b < out.body_size.size(); ++b)
    for (std::size_t k = first[b]; k < first[b + 1]; ++k)
      if (!seen[k])
        throw std::runtime_error(fmt::format("{}: body {} has no particle {} though it lists particle {} "
                                             "(expected every particle of every body once)",
                                             path.string(), b, k - first[b], out.body_size[b] - 1));
  return out;
}

std::filesystem::path frame_file(const std::filesystem::path& given) {
  if (!std::filesystem::is_directory(given)) return given;
  const auto pvd = given / "frames.pvd";
  const auto entries = read_pvd(pvd);
  if (entries.empty()) throw std::runtime_error(pvd.string() + ": lists no frame");
  return given / entries.back().file;
}

}  // namespace rkpm::io
