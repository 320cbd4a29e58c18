#pragma once
/// A ParaView time series (a .pvd and its VTU frames) written as one transaction.
#include <filesystem>
#include <hooke/io/field.hpp>
#include <hooke/io/pvd.hpp>
#include <hooke/mesh/mesh.hpp>
#include <vector>

namespace hooke::io {

/// Frames go to DIR/frames.partial/; commit() replaces DIR/frames/ and DIR/simulation.pvd with them (the old .pvd
/// is removed first, so no .pvd ever names missing frames). Destroyed without commit(), it removes the partial
/// frames and leaves DIR as it was.
class SeriesWriter {
 public:
  /// @param dir   output folder (created)
  /// @param mesh  the mesh every frame is drawn on (copied)
  /// @throws IoError when `dir` cannot be created (it exists as a file, or is not writable)
  SeriesWriter(std::filesystem::path dir, mesh::Mesh mesh);
  ~SeriesWriter();
  SeriesWriter(const SeriesWriter&) = delete;
  SeriesWriter& operator=(const SeriesWriter&) = delete;

  /// Writes one frame at time `time` (s) with point fields (#V x components each).
  void write(double time, const std::vector<Field>& point_data);
  /// Publishes the series; returns the path of simulation.pvd.
  std::filesystem::path commit();
  int frame_count() const { return static_cast<int>(m_frames.size()); }

 private:
  std::filesystem::path m_dir, m_partial;
  mesh::Mesh m_mesh;
  std::vector<PvdFrame> m_frames;
  bool m_committed = false;
};

}  // namespace hooke::io
