#pragma once
/// ParaView data collections (.pvd): a time series of VTU files.
#include <filesystem>
#include <string>
#include <vector>

namespace hooke::io {

/// One frame of a time series: time in s, file path relative to the .pvd's folder.
struct PvdFrame {
  double time = 0.0;
  std::string file;
};

/// Writes a .pvd collection listing `frames` (written atomically). The VTU files themselves are written by
/// write_vtu.
void write_pvd(const std::filesystem::path& path, const std::vector<PvdFrame>& frames);

/// Reads the frames of a .pvd collection (the DataSet elements' timestep and file attributes, in order).
/// @throws IoError if the file cannot be opened; ParseError{file, line} on a DataSet without them
std::vector<PvdFrame> read_pvd(const std::filesystem::path& path);

}  // namespace hooke::io
