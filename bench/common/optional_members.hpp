// Members the operator storage may or may not carry, depending on how the step
// kernels are written: a stored transpose of an operator (for transposed products as
// gathers), per-thread scatter buffers in the Body (for them as scatters). The
// footprint counts each when present, so the tools build against either layout and
// measure whichever one the kernels use.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

namespace rkpm::bench {

template <class T, class = void>
struct has_transpose : std::false_type {};
template <class T>
struct has_transpose<T, std::void_t<decltype(std::declval<const T&>().transpose)>> : std::true_type {};

template <class T, class = void>
struct has_force_scatter : std::false_type {};
template <class T>
struct has_force_scatter<T, std::void_t<decltype(std::declval<const T&>().force_scatter.bytes())>> : std::true_type {};

// Bytes of op.transpose (offset, entry and row arrays), 0 when the operator has none.
template <class Op>
std::size_t transpose_bytes(const Op& op) {
  if constexpr (has_transpose<Op>::value) {
    const auto& t = op.transpose;
    return t.offset.size() * sizeof(t.offset[0]) + t.entry.size() * sizeof(t.entry[0]) +
           t.row.size() * sizeof(t.row[0]);
  } else {
    return 0;
  }
}

// Bytes of the body's force scatter buffers, 0 when it has none.
template <class B>
std::size_t scatter_bytes(const B& body) {
  if constexpr (has_force_scatter<B>::value) return body.force_scatter.bytes();
  else return 0;
}

}  // namespace rkpm::bench
