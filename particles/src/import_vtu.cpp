// .vtu import: the only translation unit that sees VTK headers.
#include "rkpm/particles/element_geometry.hpp"
#include "rkpm/particles/generators.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellTypes.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <map>
#include <sstream>

namespace rkpm::particles {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw CloudError("import_vtu '" + path + "': " + what);
}

// Collects the reader's error messages for our exception instead of letting VTK
// print them to the terminal.
void collect_error(vtkObject*, unsigned long, void* client_data, void* call_data) {
  auto* messages = static_cast<std::string*>(client_data);
  if (call_data) *messages += static_cast<const char*>(call_data);
}

std::string cell_type_name(int type) {
  const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
  return (name ? std::string(name) : std::string("unknown")) + " (VTK type " + std::to_string(type) + ")";
}

}  // namespace

Cloud import_vtu(const std::string& path) {
  if (!std::ifstream(path).good()) fail(path, "cannot open the file for reading");

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(path.c_str())) fail(path, "not a VTK XML UnstructuredGrid (.vtu) file");
  std::string errors;
  vtkNew<vtkCallbackCommand> on_error;
  on_error->SetCallback(collect_error);
  on_error->SetClientData(&errors);
  reader->AddObserver(vtkCommand::ErrorEvent, on_error);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (!errors.empty() || grid == nullptr) fail(path, "the reader failed: " + errors);

  const vtkIdType n_points = grid->GetNumberOfPoints();
  if (n_points == 0) fail(path, "the grid has no points");

  std::map<int, vtkIdType> unsupported;  // cell type -> count
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const int type = grid->GetCellType(c);
    if (type != VTK_TETRA && type != VTK_HEXAHEDRON) ++unsupported[type];
  }
  if (!unsupported.empty()) {
    std::ostringstream msg;
    msg << "unsupported cell types (only VTK_TETRA and VTK_HEXAHEDRON are accepted):";
    for (const auto& [type, count] : unsupported) msg << " " << count << " x " << cell_type_name(type) << ";";
    fail(path, msg.str());
  }
  if (grid->GetNumberOfCells() == 0) fail(path, "the grid has no cells");

  Cloud cloud;
  cloud.name = path;
  cloud.X.resize(n_points);
  for (vtkIdType p = 0; p < n_points; ++p) {
    double x[3];
    grid->GetPoint(p, x);
    cloud.X[p] = Vec3(x[0], x[1], x[2]);
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    std::int32_t nodes[8];
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) nodes[k] = static_cast<std::int32_t>(ids->GetId(k));
    cloud.mesh.add_element(grid->GetCellType(c) == VTK_TETRA ? ElementType::Tet4 : ElementType::Hex8, nodes);
  }

  // Inverted cells are the usual defect of exported meshes (node order of a
  // mirrored part): report how many, not only the first, before finalize_cloud.
  int inverted = 0, first_inverted = -1;
  for (int e = 0; e < cloud.mesh.n_elements(); ++e) {
    if (element_min_scaled_jacobian(cloud, e) <= 0.0) {
      if (inverted++ == 0) first_inverted = e;
    }
  }
  if (inverted > 0) {
    fail(path, std::to_string(inverted) + " of " + std::to_string(cloud.mesh.n_elements()) +
                   " cells are inverted or degenerate (first: cell " + std::to_string(first_inverted) +
                   "); expected VTK node order with positive volume");
  }

  // The file carries no surface names: the whole surface is "surface".
  cloud.surface_names = {"surface"};
  finalize_cloud(cloud);
  for (const std::int32_t p : cloud.boundary_particles) cloud.surface_mask[p] = 1;
  return cloud;
}

}  // namespace rkpm::particles
