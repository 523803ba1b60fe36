// What the terms' build functions share: finding the bodies a [[term]] names, and
// turning a term's own std::invalid_argument into a SetupError that names the table.
#pragma once

#include "rkpm/scene/param_set.hpp"
#include "rkpm/sim/build.hpp"
#include "rkpm/sim/world.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace rkpm::terms {

// The body called `name` in the world. The scene loader has checked the name, so a
// miss means the world and the scene disagree: a SetupError naming the table.
inline sim::Body& named_body(sim::World& world, const scene::ParamSet& p, const std::string& name) {
  sim::Body* body = world.find_body(name);
  if (!body)
    throw sim::SetupError(fmt::format("{}:{}: [term] body \"{}\": no such body", p.file(), p.table_line(), name));
  return *body;
}

// Runs `make` (a term's constructor), reporting its std::invalid_argument as a
// SetupError at the [[term]] table's line.
template <class Make>
auto constructed(const scene::ParamSet& p, Make&& make) -> decltype(make()) {
  try {
    return std::forward<Make>(make)();
  } catch (const std::invalid_argument& e) {
    throw sim::SetupError(fmt::format("{}:{}: [term] {}", p.file(), p.table_line(), e.what()));
  }
}

}  // namespace rkpm::terms
