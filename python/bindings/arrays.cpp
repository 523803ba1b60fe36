#include "arrays.hpp"

namespace rkpm::python {
namespace {

py::array read_only(py::array a) {
  // Writing into the state behind the integrator's back would leave its derived fields
  // (F, stresses, the ledger) stale: the views are read-only.
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

}  // namespace

py::array vectors_view(const std::vector<Vec3>& values, py::handle owner) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  const auto n = static_cast<py::ssize_t>(values.size());
  return read_only(py::array_t<double>({n, py::ssize_t{3}}, {py::ssize_t{sizeof(Vec3)}, py::ssize_t{sizeof(double)}},
                                       values.empty() ? nullptr : values.front().data(), owner));
}

py::array field_view(const double* values, std::size_t n, int components, py::handle owner) {
  const auto rows = static_cast<py::ssize_t>(n);
  const auto cols = static_cast<py::ssize_t>(components);
  if (components == 1)
    return read_only(py::array_t<double>({rows}, {py::ssize_t{sizeof(double)}}, values, owner));
  return read_only(py::array_t<double>({rows, cols}, {cols * py::ssize_t{sizeof(double)}, py::ssize_t{sizeof(double)}},
                                       values, owner));
}

py::array scalars_view(const std::vector<double>& values, py::handle owner) {
  return read_only(py::array_t<double>({static_cast<py::ssize_t>(values.size())}, {py::ssize_t{sizeof(double)}},
                                       values.data(), owner));
}

py::array matrices_view(const std::vector<Mat3>& values, py::handle owner) {
  static_assert(sizeof(Mat3) == 9 * sizeof(double), "Mat3 must be nine packed doubles");
  const auto n = static_cast<py::ssize_t>(values.size());
  constexpr auto d = static_cast<py::ssize_t>(sizeof(double));
  // Row r, column c of matrix k is at k * 9 + c * 3 + r doubles (column-major).
  return read_only(py::array_t<double>({n, py::ssize_t{3}, py::ssize_t{3}}, {9 * d, d, 3 * d},
                                       values.empty() ? nullptr : values.front().data(), owner));
}

py::array copied(std::vector<double>&& values, int components) {
  auto* heap = new std::vector<double>(std::move(values));
  py::capsule free_when_done(heap, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto n = static_cast<py::ssize_t>(heap->size() / static_cast<std::size_t>(components));
  constexpr auto d = static_cast<py::ssize_t>(sizeof(double));
  if (components == 1) return py::array_t<double>({n}, {d}, heap->data(), free_when_done);
  if (components == 9)
    return py::array_t<double>({n, py::ssize_t{3}, py::ssize_t{3}}, {9 * d, 3 * d, d}, heap->data(), free_when_done);
  return py::array_t<double>({n, py::ssize_t{components}}, {components * d, d}, heap->data(), free_when_done);
}

}  // namespace rkpm::python
