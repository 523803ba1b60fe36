// The only translation unit that includes VTK.
#include "rkpm/io/vtu_writer.hpp"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rkpm::io {

namespace {

vtkNew<vtkDoubleArray> to_vtk_array(const PointField& field) {
  vtkNew<vtkDoubleArray> array;
  array->SetName(field.name.c_str());
  array->SetNumberOfComponents(field.components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(field.tuples()));
  std::copy(field.values.begin(), field.values.end(), array->GetPointer(0));
  return array;
}

vtkNew<vtkPoints> to_vtk_points(const std::vector<Vec3>& positions) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
  }
  return points;
}

vtkNew<vtkTypeInt64Array> to_vtk_int64(const std::vector<std::int64_t>& values) {
  vtkNew<vtkTypeInt64Array> array;
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

// A failed open leaves the system errno in the writer's error code; VTK's own
// codes start at FirstVTKErrorCode. (vtkErrorCode's string table lives in
// VTK::CommonMisc; naming the few codes a writer raises keeps the link line short.)
std::string describe_write_error(unsigned long code) {
  if (code < vtkErrorCode::FirstVTKErrorCode) return std::system_category().message(static_cast<int>(code));
  switch (code) {
    case vtkErrorCode::CannotOpenFileError: return "cannot open the file";
    case vtkErrorCode::OutOfDiskSpaceError: return "out of disk space";
    case vtkErrorCode::NoFileNameError: return "no file name";
    default: return fmt::format("VTK error code {}", code);
  }
}

void set_cells(vtkUnstructuredGrid* grid, const CellBlock& block) {
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfTuples(static_cast<vtkIdType>(block.types.size()));
  std::copy(block.types.begin(), block.types.end(), types->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(to_vtk_int64(block.offsets), to_vtk_int64(block.connectivity));
  grid->SetCells(types, cells);
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const Frame& frame) {
  validate_frame(frame);

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(to_vtk_points(*frame.points));
  set_cells(grid, frame.cells);
  for (const PointField& field : frame.point_fields) grid->GetPointData()->AddArray(to_vtk_array(field));
  for (const PointField& field : frame.field_data) grid->GetFieldData()->AddArray(to_vtk_array(field));
  if (!frame.duplicate_points.empty()) {
    vtkNew<vtkUnsignedCharArray> ghost;
    ghost->SetName(vtkDataSetAttributes::GhostArrayName());
    ghost->SetNumberOfTuples(static_cast<vtkIdType>(frame.duplicate_points.size()));
    for (std::size_t i = 0; i < frame.duplicate_points.size(); ++i)
      ghost->SetValue(static_cast<vtkIdType>(i), frame.duplicate_points[i] ? vtkDataSetAttributes::DUPLICATEPOINT : 0);
    grid->GetPointData()->AddArray(ghost);
  }

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(path.string().c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw binary: smaller and faster than base64
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // frames of more than 4 GiB stay writable
  // Write() can return 1 even when the file could not be opened: the error
  // code is the reliable signal. VTK's own report of a failed write (a coloured dump of
  // the pipeline request) is held back: the error below says what failed, once.
  const bool vtk_reports = vtkObject::GetGlobalWarningDisplay() != 0;
  vtkObject::GlobalWarningDisplayOff();
  const int ok = writer->Write();
  vtkObject::SetGlobalWarningDisplay(vtk_reports ? 1 : 0);
  if (ok != 1 || writer->GetErrorCode() != vtkErrorCode::NoError) {
    throw std::runtime_error(fmt::format("VTK failed to write '{}': {}", path.string(),
                                         describe_write_error(writer->GetErrorCode())));
  }
}

}  // namespace rkpm::io
