// Label images: ITK reads and writes them (image/detail/itk_bridge.cpp); here the grid becomes world coordinates (m).
#include <algorithm>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/image/detail/itk_bridge.hpp>
#include <hooke/image/label_image.hpp>
#include <random>
#include <system_error>

namespace hooke::image {

bool is_label_image_path(const std::filesystem::path& path) {
  return detail::image_format(path) != detail::ImageFormat::kNone;
}

Vec3 LabelImage::centre(int i, int j, int k) const { return origin + direction * spacing.cwiseProduct(Vec3(i, j, k)); }

std::int32_t LabelImage::label_at(const Vec3& p, std::int32_t outside) const {
  const Vec3 index = (direction.transpose() * (p - origin)).cwiseQuotient(spacing);  // direction is orthonormal
  int ijk[3];
  for (int a = 0; a < 3; ++a) {
    const double r = std::round(index(a));
    if (!(r >= 0.0 && r < size[static_cast<std::size_t>(a)])) return outside;
    ijk[a] = static_cast<int>(r);
  }
  return at(ijk[0], ijk[1], ijk[2]);
}

std::map<std::int32_t, std::int64_t> LabelImage::histogram() const {
  std::map<std::int32_t, std::int64_t> out;
  for (const std::int32_t v : labels) ++out[v];
  return out;
}

LabelImage read_label_image(const std::filesystem::path& path, double metres_per_mm) {
  if (!is_label_image_path(path))
    throw InvalidArgument("'" + path.string() +
                          "' is not a label image (use .nii, .nii.gz, .nrrd, .nhdr, .mha or .mhd)");
  if (!(metres_per_mm > 0.0 && std::isfinite(metres_per_mm)))
    throw InvalidArgument("a label image's length scale must be a positive number");
  detail::RawLabels raw = detail::itk_read_labels(path, kMaxLabelVoxels);
  auto refuse = [&](const std::string& why) { throw ParseError::at_entry(path.string(), "header", why); };
  LabelImage out;
  out.source = path.string();
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    out.size[s] = static_cast<int>(raw.grid.size[s]);
    out.spacing(a) = raw.grid.spacing[s] * metres_per_mm;
    out.origin(a) = raw.grid.origin[s] * metres_per_mm;
    for (int b = 0; b < 3; ++b) out.direction(b, a) = raw.grid.direction[static_cast<std::size_t>(3 * b + a)];
  }
  if (!out.spacing.allFinite() || !(out.spacing.array() > 0.0).all())
    refuse("the voxel spacing must be finite and positive");
  if (!out.origin.allFinite()) refuse("the origin is not finite");
  if (!out.direction.allFinite() ||
      (out.direction.transpose() * out.direction - Mat3::Identity()).cwiseAbs().maxCoeff() > 1e-4)
    refuse("the direction matrix is not a rotation (or reflection)");
  out.labels = std::move(raw.labels);
  return out;
}

void write_label_image(const std::filesystem::path& path, const LabelImage& image) {
  using F = detail::ImageFormat;
  const F format = detail::image_format(path);
  if (format != F::kNifti && format != F::kNiftiGz && format != F::kNrrd && format != F::kMha)
    throw InvalidArgument("'" + path.string() + "': label images are written as .nii, .nii.gz, .nrrd or .mha");
  const std::int64_t voxels = static_cast<std::int64_t>(image.size[0]) * image.size[1] * image.size[2];
  if (voxels < 1 || static_cast<std::int64_t>(image.labels.size()) != voxels)
    throw InvalidArgument("write_label_image: the labels do not fill the image's size");
  detail::RawLabels raw;
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    raw.grid.size[s] = image.size[s];
    raw.grid.spacing[s] = image.spacing(a) * 1e3;
    raw.grid.origin[s] = image.origin(a) * 1e3;
    for (int b = 0; b < 3; ++b) raw.grid.direction[static_cast<std::size_t>(3 * b + a)] = image.direction(b, a);
  }
  raw.labels = image.labels;
  // A sibling with the same extension (ITK picks the format by it), renamed into place when complete.
  std::random_device rd;
  const std::filesystem::path tmp =
      path.parent_path() / (".hooke-" + std::to_string(rd()) + "-" + path.filename().string());
  try {
    detail::itk_write_labels(tmp, raw);
  } catch (...) {
    std::error_code ignore;
    std::filesystem::remove(tmp, ignore);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw IoError("cannot rename the label image into '" + path.string() + "'");
  }
}

}  // namespace hooke::image
