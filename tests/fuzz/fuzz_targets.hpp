// The fuzz targets: the scene loader, the .vtu importer, the Gmsh importer (a .msh
// read through Gmsh's API, an untrusted .geo screened and meshed) and the checkpoint
// reader, fed arbitrary bytes. Each returns normally for every input; the layer's own error (the
// answer to a bad file) is caught inside. Anything else that escapes, a crash, a
// hang or a sanitizer report is a bug.
//
// They are plain functions so the normal build can replay a corpus through them
// (test_fuzz_replay); the libFuzzer programs (RKPM_FUZZ=ON) only wrap them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rkpm::fuzz {

enum class Outcome { Accepted, Refused };

// The bytes as the text of a scene file named "fuzz.toml" (scene::parse_scene);
// scene::SceneError is the expected refusal.
Outcome scene_text(const std::uint8_t* data, std::size_t size);

// The bytes written to a temporary .vtu file and imported (particles::import_vtu);
// particles::CloudError is the expected refusal.
Outcome vtu_file(const std::uint8_t* data, std::size_t size);

// The bytes written to a temporary .msh file and imported, untrusted
// (particles::import_gmsh); particles::CloudError is the expected refusal.
Outcome msh_file(const std::uint8_t* data, std::size_t size);

// The bytes written to a temporary .geo file and taken as `rkpm run` takes an
// untrusted script: screened, its node bound estimated (a bound above
// kGeoNodeBudget is refused, as the pre-flight refuses one above its memory
// budget), then meshed at mesh_size 0.25 and imported. particles::CloudError is the
// expected refusal.
inline constexpr double kGeoNodeBudget = 20000;
Outcome geo_file(const std::uint8_t* data, std::size_t size);

// The bytes, sealed with the checkpoint's closing digest, written to a temporary file
// and read into a world freshly built from a small scene (an LCE body with its
// director, a Mooney-Rivlin block, contact between them: see fuzz_targets.cpp) by
// sim::read_checkpoint. The seal lets the fuzzer reach the fields instead of stopping
// at the digest (the digest check itself is tested in test_checkpoint). The expected
// refusal is read_checkpoint's error naming the file; an accepted checkpoint must
// leave every position, velocity, force and director finite.
Outcome checkpoint_file(const std::uint8_t* data, std::size_t size);

// A valid checkpoint of that world without its closing digest: a seed for
// checkpoint_file, which must accept it.
std::string checkpoint_seed();

}  // namespace rkpm::fuzz
