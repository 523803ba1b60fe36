// The two fuzz targets: the scene loader and the .vtu importer, fed arbitrary
// bytes. Each returns normally for every input; the layer's own error (the
// answer to a bad file) is caught inside. Anything else that escapes, a crash, a
// hang or a sanitizer report is a bug.
//
// They are plain functions so the normal build can replay a corpus through them
// (test_fuzz_replay); the libFuzzer programs (RKPM_FUZZ=ON) only wrap them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rkpm::fuzz {

enum class Outcome { Accepted, Refused };

// The bytes as the text of a scene file named "fuzz.toml" (scene::parse_scene);
// scene::SceneError is the expected refusal.
Outcome scene_text(const std::uint8_t* data, std::size_t size);

// The bytes written to a temporary .vtu file and imported (particles::import_vtu);
// particles::CloudError is the expected refusal.
Outcome vtu_file(const std::uint8_t* data, std::size_t size);

}  // namespace rkpm::fuzz
