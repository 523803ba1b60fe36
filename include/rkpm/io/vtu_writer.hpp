// Writing one frame as a VTK XML unstructured grid (.vtu). VTK itself stays
// inside vtu_writer.cpp so that no other translation unit pays for its headers.
#pragma once

#include "rkpm/io/frame.hpp"

#include <filesystem>

namespace rkpm::io {

// Validates `frame` (validate_frame), then writes it to `path` directly in
// appended mode, raw binary (not base64), zlib-compressed, 64-bit headers.
// Points are stored as float64 so values read back bit-for-bit. Not atomic on
// its own: PvdSeries writes through a temporary and renames.
// Throws FrameError / NonFiniteValue before touching the file system, and
// std::runtime_error naming the file if VTK fails to write.
void write_vtu(const std::filesystem::path& path, const Frame& frame);

}  // namespace rkpm::io
