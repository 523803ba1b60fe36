#include "rkpm/par/partition.hpp"

#include "rkpm/rk/element_edges.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rkpm::par {

namespace {
// The undirected graph of the mesh's element edges, in compressed rows (METIS's xadj,
// adjncy), each neighbour list sorted and free of repeats.
void edge_graph(const particles::Cloud& cloud, std::vector<idx_t>& xadj, std::vector<idx_t>& adjncy) {
  const std::size_t n = cloud.size();
  std::vector<std::vector<idx_t>> adjacent(n);
  const auto& mesh = cloud.mesh;
  for (int e = 0; e < mesh.n_elements(); ++e) {
    const std::int32_t* nodes = mesh.element_nodes(e);
    for (const auto& edge : rk::element_edges(mesh.type[static_cast<std::size_t>(e)])) {
      const auto a = nodes[edge[0]], b = nodes[edge[1]];
      adjacent[static_cast<std::size_t>(a)].push_back(b);
      adjacent[static_cast<std::size_t>(b)].push_back(a);
    }
  }
  xadj.assign(n + 1, 0);
  adjncy.clear();
  for (std::size_t i = 0; i < n; ++i) {
    auto& a = adjacent[i];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    adjncy.insert(adjncy.end(), a.begin(), a.end());
    xadj[i + 1] = static_cast<idx_t>(adjncy.size());
  }
}
}  // namespace

Partition partition_cloud(const particles::Cloud& cloud, int parts, PartitionMethod method) {
  const auto n = static_cast<Index>(cloud.size());
  if (parts < 1 || parts > n)
    throw std::invalid_argument(fmt::format("cannot split the {} particles of cloud '{}' into {} parts: a part "
                                            "needs at least one particle (run on at most {} ranks)",
                                            n, cloud.name, parts, n));
  Partition p;
  p.order.resize(static_cast<std::size_t>(n));
  std::iota(p.order.begin(), p.order.end(), 0);
  p.offset = {0, n};
  if (parts == 1) return p;
  if (method == PartitionMethod::kCurve) {
    // Equal ranges of the cloud's order; the first n % parts ranges one longer.
    const Index base = n / parts, extra = n % parts;
    p.offset.assign(static_cast<std::size_t>(parts) + 1, 0);
    for (int r = 0; r < parts; ++r)
      p.offset[static_cast<std::size_t>(r) + 1] = p.offset[static_cast<std::size_t>(r)] + base + (r < extra ? 1 : 0);
    return p;
  }

  std::vector<idx_t> xadj, adjncy;
  edge_graph(cloud, xadj, adjncy);
  idx_t vertices = n, constraints = 1, nparts = parts, cut = 0;
  std::vector<idx_t> part(static_cast<std::size_t>(n), 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;        // deterministic
  options[METIS_OPTION_NUMBERING] = 0;
  const int status = METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(), nullptr, nullptr,
                                         nullptr, &nparts, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error(fmt::format("METIS could not partition cloud '{}' ({} particles) into {} parts "
                                         "(status {})", cloud.name, n, parts, status));
  // Counting sort by part: stable, so each part keeps the cloud's order.
  std::vector<Index> count(static_cast<std::size_t>(parts) + 1, 0);
  for (idx_t q : part) ++count[static_cast<std::size_t>(q) + 1];
  for (int r = 0; r < parts; ++r) {
    if (count[static_cast<std::size_t>(r) + 1] == 0)
      throw std::invalid_argument(fmt::format("cloud '{}' ({} particles) leaves rank {} of {} without particles: "
                                              "run it on fewer ranks", cloud.name, n, r, parts));
    count[static_cast<std::size_t>(r) + 1] += count[static_cast<std::size_t>(r)];
  }
  p.offset = count;
  for (Index i = 0; i < n; ++i) p.order[static_cast<std::size_t>(count[static_cast<std::size_t>(part[i])]++)] = i;
  return p;
}

std::int64_t cut_edges(const particles::Cloud& cloud, const std::vector<Index>& offset) {
  const auto owner = [&](Index i) {
    return static_cast<int>(std::upper_bound(offset.begin(), offset.end(), i) - offset.begin()) - 1;
  };
  std::vector<idx_t> xadj, adjncy;
  edge_graph(cloud, xadj, adjncy);
  std::int64_t cut = 0;
  for (Index i = 0; i < static_cast<Index>(cloud.size()); ++i)
    for (idx_t k = xadj[i]; k < xadj[i + 1]; ++k)
      if (adjncy[k] > i && owner(adjncy[k]) != owner(i)) ++cut;
  return cut;
}

}  // namespace rkpm::par
