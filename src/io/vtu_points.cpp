#include "rkpm/io/vtu_points.hpp"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <stdexcept>

namespace rkpm::io {

std::vector<Vec3> read_vtu_points(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error(path.string() + ": no such file (expected a .vtu frame written by rkpm run)");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(path.string().c_str()))
    throw std::runtime_error(path.string() + ": not a VTK XML unstructured-grid (.vtu) file");
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkPoints* points = reader->GetErrorCode() == 0 ? reader->GetOutput()->GetPoints() : nullptr;
  if (points == nullptr || points->GetNumberOfPoints() == 0)
    throw std::runtime_error(path.string() + ": VTK read no points from it (expected a frame with particles)");
  std::vector<Vec3> out(static_cast<std::size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double x[3];
    points->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw std::runtime_error(path.string() + ": point " + std::to_string(i) + " is not finite");
    out[static_cast<std::size_t>(i)] = Vec3(x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace rkpm::io
