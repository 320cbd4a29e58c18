// ITK behind plain types (itk_bridge.hpp). The image IO classes are chosen by extension: no factory registration, no
// ITK_USE_FILE. No hooke header that includes Eigen may be included here.
#include <itkBinaryMask3DMeshSource.h>
#include <itkBinaryThresholdImageFilter.h>
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageIOBase.h>
#include <itkMesh.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>
#include <itkSmoothingRecursiveGaussianImageFilter.h>
#include <zlib.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <hooke/core/error.hpp>
#include <hooke/image/detail/itk_bridge.hpp>
#include <system_error>
#include <utility>
#include <vector>

namespace hooke::image::detail {
namespace {

using Labels = itk::Image<std::int32_t, 3>;
using Real = itk::Image<float, 3>;
using Mask = itk::Image<unsigned char, 3>;

itk::ImageIOBase::Pointer io_for(const std::filesystem::path& path) {
  switch (image_format(path)) {
    case ImageFormat::kNifti:
    case ImageFormat::kNiftiGz: return itk::NiftiImageIO::New().GetPointer();
    case ImageFormat::kNrrd:
    case ImageFormat::kNhdr: return itk::NrrdImageIO::New().GetPointer();
    case ImageFormat::kMha:
    case ImageFormat::kMhd: return itk::MetaImageIO::New().GetPointer();
    case ImageFormat::kNone: break;
  }
  throw InvalidArgument("'" + path.string() + "' is not a label image (use .nii, .nii.gz, .nrrd, .nhdr, .mha or .mhd)");
}

// `text` in lower case (ASCII): file extensions and MetaImage keys compare without case.
std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& why) {
  throw ParseError::at_entry(path.string(), "header", why);
}

// The first line of an ITK exception's description (without ITK's own source file and line).
std::string reason(const itk::ExceptionObject& e) {
  std::string d = e.GetDescription();
  if (d.empty()) d = e.what();
  return d.substr(0, d.find('\n'));
}

bool integer_component(itk::IOComponentEnum c) {
  using C = itk::IOComponentEnum;
  return c == C::UCHAR || c == C::CHAR || c == C::USHORT || c == C::SHORT || c == C::UINT || c == C::INT ||
         c == C::ULONG || c == C::LONG || c == C::ULONGLONG || c == C::LONGLONG;
}

template <typename Image>
void set_grid(Image* image, const Grid& g) {
  typename Image::RegionType region;
  typename Image::SpacingType spacing;
  typename Image::PointType origin;
  typename Image::DirectionType direction;
  for (unsigned a = 0; a < 3; ++a) {
    region.SetSize(a, static_cast<itk::SizeValueType>(g.size[a]));
    spacing[a] = g.spacing[a];
    origin[a] = g.origin[a];
    for (unsigned b = 0; b < 3; ++b) direction[b][a] = g.direction[3 * b + a];
  }
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
}

// A header may declare any size; the data behind it cannot hold more than its file's bytes, deflated at most
// 1032:1 (DEFLATE's limit; gzip, NRRD's gzip and MetaImage's compression all use it). So a 64 KB file never makes
// ITK allocate gigabytes. (A detached header, .nhdr or .mhd, names its data file elsewhere: not checked here.)
void require_plausible_size(const std::filesystem::path& path, std::uint64_t bytes) {
  const ImageFormat format = image_format(path);
  if (format == ImageFormat::kNhdr || format == ImageFormat::kMhd) return;
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (!ec && bytes > 1032 * size + 65536)
    refuse(path, "declares " + std::to_string(bytes) + " bytes of voxels, more than its " + std::to_string(size) +
                     " bytes can hold even compressed");
}

// ITK's MetaImage reader prints "data not read completely" and returns a half-read image for a truncated
// uncompressed .mha: such a file (its data LOCAL, after the header line "ElementDataFile = LOCAL") must hold every
// voxel's bytes.
void require_local_data(const std::filesystem::path& path, std::uint64_t bytes) {
  const ImageFormat format = image_format(path);
  if (format == ImageFormat::kNifti || format == ImageFormat::kNiftiGz) {
    // NIfTI's reader does not notice a short (or short once inflated) file either: the data follows a header of at
    // least 348 bytes, so the inflated file must be at least that much longer than the voxels.
    gzFile in = gzopen(path.c_str(), "rb");
    if (!in) refuse(path, "cannot be opened by zlib");
    std::vector<char> buffer(1 << 16);
    std::uint64_t total = 0;
    int got = 0;
    while ((got = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0)
      total += static_cast<std::uint64_t>(got);
    int status = Z_OK;
    gzerror(in, &status);
    gzclose(in);
    if (got < 0 || (status != Z_OK && status != Z_STREAM_END) || total < 348 + bytes)
      refuse(path, "the file ends before its " + std::to_string(bytes) + " bytes of voxel data");
    return;
  }
  if (format != ImageFormat::kMha) return;
  std::ifstream in(path, std::ios::binary);
  std::string head(65536, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.find("CompressedData = True") != std::string::npos) return;  // zlib reports its own truncation
  const std::size_t at = head.find("ElementDataFile = LOCAL");
  if (at == std::string::npos) return;
  const std::size_t end = head.find('\n', at);
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (end == std::string::npos || ec || size < end + 1 + bytes)
    refuse(path, "the file ends before its " + std::to_string(bytes) + " bytes of voxel data");
}

// Two MetaImage header fields ITK's reader trusts (both found by fuzzing: tests/fuzz/regressions/mha):
// - NDims: it reads NDims values for each of DimSize, ElementSpacing, Offset and the like, and NDims^2 for the
//   transform, without bounding NDims: "NDims = -1" made it read 2^32 values (a hang). A label image is 3D, so the
//   header must say NDims = 3.
// - ElementDataFile: a file pattern ("name%03d.raw first last step") or LIST spreads the voxels over several files,
//   and a step of 0 divided by zero (SIGFPE). hooke reads one file: LOCAL (the voxels follow the header; required
//   in a .mha) or, in a .mhd, one data file's name.
void require_simple_meta_header(const std::filesystem::path& path) {
  const ImageFormat format = image_format(path);
  if (format != ImageFormat::kMha && format != ImageFormat::kMhd) return;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int n = 0; n < 4096 && std::getline(in, line); ++n) {
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    auto trim = [](std::string& t) {
      const std::size_t a = t.find_first_not_of(" \t\r"), b = t.find_last_not_of(" \t\r");
      t = a == std::string::npos ? std::string() : t.substr(a, b - a + 1);
    };
    trim(key);
    trim(value);
    key = lowered(key);
    if (key == "elementdatafile") {  // the header's last field
      const std::string lower = lowered(value);
      if (format == ImageFormat::kMha ? lower != "local"
                                      : (lower == "list" || value.find_first_of("% \t") != std::string::npos))
        refuse(path, "ElementDataFile = " + value.substr(0, 60) +
                         ": the voxels must follow the header (LOCAL) or, in a .mhd, be one data file");
      return;
    }
    if (key == "ndims" && value != "3")
      refuse(path, "a label image must be 3D, this header declares NDims = " + value.substr(0, 40));
  }
}

// ITK's NIfTI reader takes the header's orientation (the quaternion, its offsets and the sform rows) to a
// single-precision SVD that aborts the process on a non-finite number and does not return when squares of the
// entries overflow (both found by fuzzing: tests/fuzz/regressions/nii). So every float of a NIfTI-1 header that
// describes the grid (pixdim, vox_offset, the scaling, the quaternion, the offsets and the sform rows, bytes 76-119
// and 256-327) must be finite and at most 1e9 in magnitude (a kilometre in mm) before ITK reads it. A header of
// another size is left to ITK.
void require_finite_nifti_geometry(const std::filesystem::path& path) {
  const ImageFormat format = image_format(path);
  if (format != ImageFormat::kNifti && format != ImageFormat::kNiftiGz) return;
  gzFile in = gzopen(path.c_str(), "rb");  // reads an uncompressed file as it is
  if (!in) refuse(path, "cannot be opened by zlib");
  unsigned char header[348];
  const int got = gzread(in, header, sizeof header);
  gzclose(in);
  if (got != static_cast<int>(sizeof header)) return;  // too short for a header: ITK says what it is not
  auto word = [&](int at, bool swap) {
    std::uint32_t w = 0;
    for (int b = 0; b < 4; ++b)
      w |= static_cast<std::uint32_t>(header[at + (swap ? 3 - b : b)]) << (8 * b);  // little-endian unless swapped
    return w;
  };
  bool swap = false;
  if (word(0, false) != 348) {
    if (word(0, true) != 348) return;  // not a NIfTI-1 header
    swap = true;
  }
  for (const auto& [first, end] : {std::pair{76, 120}, std::pair{256, 328}})
    for (int at = first; at < end; at += 4) {
      const std::uint32_t w = word(at, swap);
      float f = 0.0f;
      std::memcpy(&f, &w, sizeof f);
      if (!(std::abs(f) <= 1e9f))
        refuse(path, "the header's grid geometry (spacing, offset or orientation, byte " + std::to_string(at) +
                         ") is not a finite number of at most 1e9");
    }
}

}  // namespace

ImageFormat image_format(const std::filesystem::path& path) {
  const std::string name = lowered(path.filename().string());
  const std::pair<const char*, ImageFormat> formats[] = {
      {".nii.gz", ImageFormat::kNiftiGz}, {".nii", ImageFormat::kNifti}, {".nrrd", ImageFormat::kNrrd},
      {".nhdr", ImageFormat::kNhdr},      {".mha", ImageFormat::kMha},   {".mhd", ImageFormat::kMhd}};
  for (const auto& [ext, format] : formats)
    if (name.size() > std::string(ext).size() && name.ends_with(ext)) return format;
  return ImageFormat::kNone;
}

namespace {

RawLabels read_labels(const std::filesystem::path& path, std::int64_t max_voxels) {
  static const bool quiet = (itk::Object::GlobalWarningDisplayOff(), true);  // ITK's warnings go to stdout
  (void)quiet;
  itk::ImageIOBase::Pointer io = io_for(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError("cannot open label image '" + path.string() + "'");
  require_simple_meta_header(path);
  require_finite_nifti_geometry(path);
  try {
    if (!io->CanReadFile(path.c_str())) refuse(path, "not a readable image of its extension's format");
    io->SetFileName(path.string());
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject& e) {
    refuse(path, reason(e));
  }
  const unsigned dims = io->GetNumberOfDimensions();
  if (dims != 3) refuse(path, "a label image must be 3D, this one has " + std::to_string(dims) + " dimension(s)");
  if (io->GetNumberOfComponents() != 1)
    refuse(path, "a label image has one value per voxel, this one has " + std::to_string(io->GetNumberOfComponents()));
  RawLabels out;
  std::int64_t voxels = 1;
  for (unsigned a = 0; a < 3; ++a) {
    const auto n = static_cast<std::int64_t>(io->GetDimensions(a));
    if (n < 1 || n > max_voxels) refuse(path, "size " + std::to_string(n) + " along axis " + std::to_string(a));
    voxels *= n;
    if (voxels > max_voxels)
      refuse(path, "more than " + std::to_string(max_voxels) + " voxels (the largest image hooke reads)");
    out.grid.size[a] = n;
    out.grid.spacing[a] = io->GetSpacing(a);
    out.grid.origin[a] = io->GetOrigin(a);
    const std::vector<double> d = io->GetDirection(a);
    for (unsigned b = 0; b < 3; ++b) out.grid.direction[3 * b + a] = b < d.size() ? d[b] : 0.0;
  }
  const itk::IOComponentEnum component = io->GetComponentType();
  const bool integer = integer_component(component);
  const std::uint64_t bytes = static_cast<std::uint64_t>(voxels) * io->GetComponentSize();
  require_plausible_size(path, bytes);
  require_local_data(path, bytes);
  if (!integer && component != itk::IOComponentEnum::FLOAT && component != itk::IOComponentEnum::DOUBLE)
    refuse(path, "voxel type " + itk::ImageIOBase::GetComponentTypeAsString(component) + " is not a label type");
  try {
    out.labels.resize(static_cast<std::size_t>(voxels));
    if (integer) {
      auto reader = itk::ImageFileReader<Labels>::New();
      reader->SetImageIO(io);
      reader->SetFileName(path.string());
      reader->Update();
      const std::int32_t* v = reader->GetOutput()->GetBufferPointer();
      std::copy(v, v + voxels, out.labels.begin());
    } else {  // a float image is a label image when every voxel is a whole number (some tools write them so)
      auto reader = itk::ImageFileReader<itk::Image<double, 3>>::New();
      reader->SetImageIO(io);
      reader->SetFileName(path.string());
      reader->Update();
      const double* v = reader->GetOutput()->GetBufferPointer();
      for (std::int64_t n = 0; n < voxels; ++n) {
        if (!(v[n] == std::round(v[n]) && std::abs(v[n]) < 2147483647.0))
          refuse(path, "voxel " + std::to_string(n) + " holds " + std::to_string(v[n]) + ", not a label (an integer)");
        out.labels[static_cast<std::size_t>(n)] = static_cast<std::int32_t>(v[n]);
      }
    }
  } catch (const itk::ExceptionObject& e) {
    refuse(path, reason(e));
  } catch (const std::bad_alloc&) {
    refuse(path, "out of memory reading " + std::to_string(voxels) + " voxels");
  }
  return out;
}

}  // namespace

// Every ITK exception, wherever in the header's analysis or the read it comes from (a mutated header's unknown
// voxel type makes even GetComponentSize throw), is a refusal naming the file.
RawLabels itk_read_labels(const std::filesystem::path& path, std::int64_t max_voxels) {
  try {
    return read_labels(path, max_voxels);
  } catch (const Error&) {
    throw;
  } catch (const itk::ExceptionObject& e) {
    refuse(path, reason(e));
  } catch (const std::bad_alloc&) {
    refuse(path, "out of memory");
  } catch (const std::exception& e) {
    refuse(path, e.what());
  }
}

void itk_write_labels(const std::filesystem::path& path, const RawLabels& image) {
  auto out = Labels::New();
  set_grid(out.GetPointer(), image.grid);
  std::copy(image.labels.begin(), image.labels.end(), out->GetBufferPointer());
  try {
    auto writer = itk::ImageFileWriter<Labels>::New();
    writer->SetImageIO(io_for(path));
    writer->SetFileName(path.string());
    writer->SetInput(out);
    writer->SetUseCompression(image_format(path) == ImageFormat::kNiftiGz);
    writer->Update();
  } catch (const itk::ExceptionObject& e) {
    throw IoError("cannot write label image '" + path.string() + "': " + reason(e));
  }
}

RawSurface itk_half_level_surface(const Grid& grid, const std::vector<float>& values, double sigma) {
  auto image = Real::New();
  set_grid(image.GetPointer(), grid);
  std::copy(values.begin(), values.end(), image->GetBufferPointer());
  Real::Pointer smooth = image;
  if (sigma > 0.0) {
    auto gauss = itk::SmoothingRecursiveGaussianImageFilter<Real, Real>::New();
    gauss->SetInput(image);
    itk::FixedArray<double, 3> s;
    for (unsigned a = 0; a < 3; ++a) s[a] = sigma * grid.spacing[a];
    gauss->SetSigmaArray(s);
    gauss->Update();
    smooth = gauss->GetOutput();
  }
  auto threshold = itk::BinaryThresholdImageFilter<Real, Mask>::New();
  threshold->SetInput(smooth);
  threshold->SetLowerThreshold(0.5f);
  threshold->SetUpperThreshold(1e30f);
  threshold->SetInsideValue(1);
  threshold->SetOutsideValue(0);
  using Mesh = itk::Mesh<double, 3>;
  auto cubes = itk::BinaryMask3DMeshSource<Mask, Mesh>::New();
  cubes->SetInput(threshold->GetOutput());
  cubes->SetObjectValue(1);
  cubes->Update();
  const Mesh* m = cubes->GetOutput();
  RawSurface out;
  out.points.resize(m->GetNumberOfPoints());
  for (auto it = m->GetPoints()->Begin(); it != m->GetPoints()->End(); ++it)
    for (unsigned a = 0; a < 3; ++a) out.points[it.Index()][a] = it.Value()[a];
  for (auto it = m->GetCells()->Begin(); it != m->GetCells()->End(); ++it) {
    const auto* cell = it.Value();
    if (cell->GetNumberOfPoints() != 3) continue;
    std::array<int, 3> t{};
    std::size_t k = 0;
    for (auto p = cell->PointIdsBegin(); p != cell->PointIdsEnd(); ++p) t[k++] = static_cast<int>(*p);
    out.triangles.push_back(t);
  }
  return out;
}

}  // namespace hooke::image::detail
