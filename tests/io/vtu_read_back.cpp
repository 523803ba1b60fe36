#include "vtu_read_back.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <stdexcept>

namespace rkpm::io::test {

namespace {

PointField to_field(vtkDataArray* array) {
  PointField f{array->GetName() ? array->GetName() : "", array->GetNumberOfComponents(), {}};
  if (array->GetDataType() != VTK_DOUBLE) throw std::runtime_error("array '" + f.name + "' is not float64");
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t) {
    for (int c = 0; c < f.components; ++c) f.values.push_back(array->GetComponent(t, c));
  }
  return f;
}

std::vector<std::int64_t> to_int64(vtkDataArray* array) {
  std::vector<std::int64_t> values;
  for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t) {
    values.push_back(static_cast<std::int64_t>(array->GetComponent(t, 0)));
  }
  return values;
}

}  // namespace

namespace {
template <class Reader>
ReadBack read_with(const std::filesystem::path& path);
}  // namespace

ReadBack read_vtu_back(const std::filesystem::path& path) {
  if (path.extension() == ".pvtu") return read_with<vtkXMLPUnstructuredGridReader>(path);
  return read_with<vtkXMLUnstructuredGridReader>(path);
}

namespace {
template <class Reader>
ReadBack read_with(const std::filesystem::path& path) {
  vtkNew<Reader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0) throw std::runtime_error("VTK could not read " + path.string());
  vtkUnstructuredGrid* grid = reader->GetOutput();

  ReadBack out;
  vtkPoints* points = grid->GetPoints();
  if (points != nullptr) {
    out.points_are_float64 = points->GetDataType() == VTK_DOUBLE;
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
      double x[3];
      points->GetPoint(i, x);
      out.points.emplace_back(x[0], x[1], x[2]);
    }
  }
  if (vtkUnsignedCharArray* types = grid->GetCellTypesArray()) {
    for (vtkIdType c = 0; c < types->GetNumberOfTuples(); ++c) out.cells.types.push_back(types->GetValue(c));
  }
  out.cells.offsets = to_int64(grid->GetCells()->GetOffsetsArray());
  out.cells.connectivity = to_int64(grid->GetCells()->GetConnectivityArray());
  for (int a = 0; a < grid->GetPointData()->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = grid->GetPointData()->GetArray(a);
    if (array->GetName() && std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName()) {
      for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
        out.ghost_type.push_back(static_cast<std::uint8_t>(array->GetComponent(t, 0)));
      continue;
    }
    PointField f = to_field(array);
    out.point_fields[f.name] = f;
  }
  for (int a = 0; a < grid->GetFieldData()->GetNumberOfArrays(); ++a) {
    PointField f = to_field(grid->GetFieldData()->GetArray(a));
    out.field_data[f.name] = f;
  }
  return out;
}
}  // namespace

}  // namespace rkpm::io::test
