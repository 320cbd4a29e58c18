#pragma once
// The only place ITK is included (image/detail/itk_bridge.cpp), behind plain types: ITK bundles its own Eigen 3.3,
// which cannot share a translation unit with the Eigen 3.4 of hooke's headers. Lengths in the file's units (mm).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hooke::image::detail {

// The label-image formats, by file name (any case; ".nii.gz" is one extension).
enum class ImageFormat { kNone, kNifti, kNiftiGz, kNrrd, kNhdr, kMha, kMhd };
ImageFormat image_format(const std::filesystem::path& path);

struct Grid {
  std::array<std::int64_t, 3> size{0, 0, 0};
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major; column a: the direction of index a
};

// A 3D integer image read by ITK: the header checked before any voxel is read (ParseError naming the file).
struct RawLabels {
  Grid grid;
  std::vector<std::int32_t> labels;  // i fastest
};
RawLabels itk_read_labels(const std::filesystem::path& path, std::int64_t max_voxels);
// Writes 32-bit labels to `path` (the format by its extension, ".nii.gz" compressed). @throws IoError
void itk_write_labels(const std::filesystem::path& path, const RawLabels& image);

// Marching cubes (ITK's BinaryMask3DMeshSource) of `values` >= 0.5 after a Gaussian of `sigma` voxels (0: none).
struct RawSurface {
  std::vector<std::array<double, 3>> points;  // world, the grid's units
  std::vector<std::array<int, 3>> triangles;
};
RawSurface itk_half_level_surface(const Grid& grid, const std::vector<float>& values, double sigma);

}  // namespace hooke::image::detail
