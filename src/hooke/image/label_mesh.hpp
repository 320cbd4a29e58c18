#pragma once
/// From a label image to a tet mesh whose elements know their tissue (docs/images.md): the selected labels' union is
/// box-averaged to the target size, smoothed (ITK's recursive Gaussian), thresholded at one half and extracted by
/// ITK's marching cubes (BinaryMask3DMeshSource); the surface is welded, cleared of specks, Taubin-smoothed, checked
/// and filled with tets (io::tetrahedralize); each tet then takes the label most of its sample points fall in.
#include <cstdint>
#include <hooke/image/label_image.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <string>
#include <vector>

namespace hooke::image {

struct LabelMeshOptions {
  std::vector<int> labels;  ///< the labels of the body; empty: every value but 0
  /// tetrahedralize.max_size (m) is the tets' target edge (0: the labels' bounding-box diagonal / 25); the surface is
  /// extracted on voxels of about half of it; tetrahedralize.speck_fraction drops the specks
  mesh::TetrahedralizeOptions tetrahedralize;
  /// the Gaussian's sigma before the threshold, in (averaged) voxels, in [0, 10]; measured on a box with a sphere
  /// (tests/image): 1 voxel rounds a box's edges off (-1.2 % of its volume), 0.5 keeps it within 0.03 %
  double smoothing = 0.5;
  int surface_smoothing = 10;  ///< Taubin iterations on the extracted surface (mesh::taubin_smooth), >= 0
};

/// Per label: what the image holds and what the mesh made of it.
struct LabelReport {
  int label = 0;
  std::int64_t voxels = 0;
  double voxel_volume = 0.0;  ///< voxels x the voxel's volume, m^3
  int tets = 0;
  double volume = 0.0;        ///< of its tets, m^3
  double volume_error = 0.0;  ///< volume / voxel_volume - 1
  double min_dihedral = 0.0;  ///< smallest dihedral angle of its tets, degrees
};

struct LabelMesh {
  mesh::Mesh tets;                  ///< region = the label of each tet
  std::vector<LabelReport> labels;  ///< in the order of the labels
  int surface_triangles = 0;        ///< of the extracted, cleaned surface
  int welded_nodes = 0;             ///< coincident nodes of the marching cubes merged
  int dropped_pieces = 0;           ///< specks dropped
  double dropped_volume = 0.0;      ///< their volume, m^3
  int unlabelled_tets = 0;          ///< tets none of whose sample points lay in a selected label (given the nearest)
  mesh::TetrahedralizeReport meshing;
  double seconds = 0.0;  ///< wall time, image to tets
  /// One line: the image, the labels, counts, the volume errors, time.
  std::string summary() const;
};

/// The tet mesh of the labels of `image` (see the file comment).
/// @throws InvalidArgument for a label the image does not hold (naming the labels it has) or options out of range;
///   InvalidMesh when the extracted surface cannot be meshed (named as tetrahedralize does: e.g. two organs that
///   touch only along an edge), with the image named
LabelMesh labels_to_mesh(const LabelImage& image, const LabelMeshOptions& options = {});

/// Registers label images (.nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd) with io::read_mesh: read_label_image (in mm)
/// then labels_to_mesh with the defaults, so that every command that takes a mesh takes a label image. Idempotent.
void register_label_image_reader();

}  // namespace hooke::image
