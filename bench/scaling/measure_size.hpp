// The work of one child process: one geometry at one resolution, measured in a
// fresh process so that its peak memory is its own.
#pragma once

#include "../common/scenes.hpp"
#include "record.hpp"

#include <string>

namespace rkpm::scaling {

struct MeasureSettings {
  int warmup = 2;         // steps before timing (first-touch, caches, the first dt estimate)
  int steps = 5;          // timed steps with 2 threads (median)
  int steps_1t = 3;       // timed steps with 1 thread (median)
  bool split = true;      // time the parts of build_world again one by one
  std::string rbc_scene;  // examples/rbc/rbc.toml
  // The [body.rk] keys of every geometry: the lean set-up unless asked otherwise.
  bench::RkChoices rk{"ellipsoid", "morton", "float"};
};

// Throws on set-up errors; the caller reports them as a failed size.
SizeResult measure_size(bench::Geometry geometry, int resolution, const MeasureSettings& settings);

}  // namespace rkpm::scaling
