#pragma once
/// Label images (a segmentation: one integer per voxel, 0 or another value outside, one value per tissue) read and
/// written with ITK (Debian's libinsighttoolkit5: NIfTI .nii/.nii.gz, NRRD .nrrd/.nhdr, MetaImage .mha/.mhd),
/// with the voxel grid's spacing, origin and direction (docs/images.md).
#include <array>
#include <cstdint>
#include <filesystem>
#include <hooke/core/types.hpp>
#include <map>
#include <string>
#include <vector>

namespace hooke::image {

/// A 3D label image in world coordinates (m): voxel (i, j, k) has its centre at origin + direction diag(spacing)
/// (i, j, k)^T, as ITK (and DICOM, NIfTI's qform) define it.
struct LabelImage {
  std::array<int, 3> size{0, 0, 0};   ///< voxels along i, j, k (each >= 1)
  Vec3 spacing = Vec3::Ones();        ///< voxel size along i, j, k, m (> 0)
  Vec3 origin = Vec3::Zero();         ///< centre of voxel (0, 0, 0), m
  Mat3 direction = Mat3::Identity();  ///< columns: the world directions of i, j, k (orthonormal)
  std::vector<std::int32_t> labels;   ///< size[0] size[1] size[2] values, i fastest
  std::string source;                 ///< file name, for messages

  std::int64_t voxel_count() const { return static_cast<std::int64_t>(labels.size()); }
  /// The label of voxel (i, j, k). @pre in range
  std::int32_t at(int i, int j, int k) const {
    return labels[static_cast<std::size_t>(i + static_cast<std::int64_t>(size[0]) *
                                                   (j + static_cast<std::int64_t>(size[1]) * k))];
  }
  /// World position of the centre of voxel (i, j, k), m.
  Vec3 centre(int i, int j, int k) const;
  /// The label of the voxel containing world point `p` (m), or `outside` beyond the image.
  std::int32_t label_at(const Vec3& p, std::int32_t outside = 0) const;
  double voxel_volume() const { return spacing.prod(); }  ///< m^3
  /// Voxels per label value, in increasing label order.
  std::map<std::int32_t, std::int64_t> histogram() const;
};

/// Largest image read, in voxels (2^31: 8 GB as labels); larger headers are refused before any voxel is read.
inline constexpr std::int64_t kMaxLabelVoxels = std::int64_t{1} << 31;

/// True when `path` names a label image format hooke reads (.nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd; any case).
bool is_label_image_path(const std::filesystem::path& path);

/// Reads a 3D label image. Spacing and origin are read in millimetres (the unit ITK reports NIfTI's in, and the
/// convention of NRRD and MetaImage) and scaled by `metres_per_mm` (1e-3: to metres).
/// Refused with a ParseError naming the file and why: an unreadable or truncated file, not 3D (a 2D image, a 4D
/// series), more than one component per voxel, non-integer voxel values (a float image that is not a
/// segmentation), more than kMaxLabelVoxels voxels, spacing not finite and > 0, a direction that is not a rotation
/// or reflection; IoError when the file cannot be opened.
LabelImage read_label_image(const std::filesystem::path& path, double metres_per_mm = 1e-3);

/// Writes `image` (world units m, written as mm) as .nii/.nii.gz, .nrrd or .mha (one file each), 32-bit integer
/// voxels, atomically (a temporary file beside it renamed when complete). @throws IoError; InvalidArgument for
/// another extension (the detached .nhdr and .mhd are read, not written)
void write_label_image(const std::filesystem::path& path, const LabelImage& image);

}  // namespace hooke::image
