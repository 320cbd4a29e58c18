#pragma once
/// A ParaView time series (a .pvd and its VTU frames) written as one transaction.
#include <filesystem>
#include <hooke/io/field.hpp>
#include <hooke/io/pvd.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <vector>

namespace hooke::io {

/// Kill-safe at any instant: frames go to DIR/frames-ID.partial/ (ID unique to this writer); commit() renames it to
/// DIR/frames-ID/, then replaces DIR/simulation.pvd atomically (the commit point: before it the old .pvd and its
/// frames are whole, after it the new ones), then removes the frames no .pvd names any more (older frames-* folders,
/// the pre-0.4 frames/ folder, partial folders of killed runs). Destroyed without commit(), it removes its own
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
  std::string m_name;          // frames-ID
  bool m_created_dir = false;  // the output folder did not exist before
  mesh::Mesh m_mesh;
  std::vector<PvdFrame> m_frames;
  bool m_committed = false;
};

}  // namespace hooke::io
