// Label images (image/): ITK's readers and writers with the grid honoured, hostile headers refused, and labels to a
// tet mesh whose regions hold each label's volume; a real segmentation from a Debian package (ITK's examples).
#include <gtest/gtest.h>

#include <support/scratch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/image/label_image.hpp>
#include <hooke/image/label_mesh.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/measure.hpp>
#include <iostream>
#include <limits>
#include <random>
#include <string>

namespace hooke::image {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratch_file("hooke_label_image_tests", name); }

// A 40 x 36 x 30 image of 1 mm x 1.25 mm x 1.5 mm voxels, turned 90 degrees about z and shifted: label 1 a box,
// label 2 a sphere of radius 8 mm inside it, 0 outside.
constexpr int kNx = 40, kNy = 36, kNz = 30;
LabelImage sphere_in_box() {
  LabelImage img;
  img.size = {kNx, kNy, kNz};
  img.spacing = Vec3(1e-3, 1.25e-3, 1.5e-3);
  img.origin = Vec3(0.05, -0.02, 0.01);
  img.direction << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  img.labels.assign(kNx * kNy * kNz, 0);
  img.source = "sphere in a box";
  const Vec3 centre(19.5, 22.0, 22.0);  // mm in the grid's own axes
  for (int k = 2; k < kNz - 2; ++k)
    for (int j = 2; j < kNy - 2; ++j)
      for (int i = 2; i < kNx - 2; ++i)
        img.labels[static_cast<std::size_t>(i + kNx * (j + kNy * k))] =
            (Vec3(i * 1.0, j * 1.25, k * 1.5) - centre).norm() < 8.0 ? 2 : 1;
  return img;
}

TEST(LabelImage, RoundTripsThroughEachFormatWithItsGrid) {
  const LabelImage img = sphere_in_box();
  for (const char* name : {"a.nii.gz", "a.nii", "a.nrrd", "a.mha"}) {
    const fs::path path = scratch(name);
    write_label_image(path, img);
    const LabelImage back = read_label_image(path);
    EXPECT_EQ(back.size, img.size) << name;
    EXPECT_LT((back.spacing - img.spacing).norm(), 1e-9) << name;
    EXPECT_LT((back.origin - img.origin).norm(), 1e-9) << name;
    EXPECT_LT((back.direction - img.direction).norm(), 1e-6) << name;
    EXPECT_EQ(back.labels, img.labels) << name;
    // the voxel (3, 4, 5) is at origin + direction (spacing * index), and label_at finds it there
    const Vec3 c = back.centre(3, 4, 5);
    EXPECT_LT((c - (img.origin + img.direction * Vec3(3e-3, 5e-3, 7.5e-3))).norm(), 1e-12) << name;
    EXPECT_EQ(back.label_at(back.centre(11, 9, 7)), img.at(11, 9, 7)) << name;
    EXPECT_EQ(back.label_at(Vec3(10, 10, 10)), 0) << name;  // far outside
    fs::remove(path);
  }
  EXPECT_THROW(write_label_image(scratch("a.png"), img), InvalidArgument);
}

// Each hostile file: a ParseError naming it (exit 2 in the CLI), never a crash or an allocation the header asks for.
TEST(LabelImage, RefusesHostileFiles) {
  const LabelImage img = sphere_in_box();
  write_label_image(scratch("good.mha"), img);
  std::string good;
  {
    std::ifstream in(scratch("good.mha"), std::ios::binary);
    good.assign(std::istreambuf_iterator<char>(in), {});
  }
  write_label_image(scratch("good.nii.gz"), img);
  std::string nii_gz;
  {
    std::ifstream in(scratch("good.nii.gz"), std::ios::binary);
    nii_gz.assign(std::istreambuf_iterator<char>(in), {});
  }
  write_label_image(scratch("good.nii"), img);
  std::string nii;
  {
    std::ifstream in(scratch("good.nii"), std::ios::binary);
    nii.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::string nan_sform = nii;  // srow_x[0] (byte 280) a NaN: ITK's orientation SVD aborted the process on it
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan_sform.data() + 280, &nan, sizeof nan);
  auto write = [](const std::string& name, const std::string& text) {
    std::ofstream(scratch(name), std::ios::binary) << text;
    return scratch(name);
  };
  auto header_replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  const struct {
    std::string name, text;
  } cases[] = {
      {"empty.mha", ""},
      {"text.mha", "not an image at all\n"},
      {"truncated.mha", good.substr(0, good.size() - 100)},
      {"huge.mha", header_replaced("DimSize = 40 36 30", "DimSize = 100000 100000 100000")},
      {"flat.mha", header_replaced("NDims = 3", "NDims = 2")},
      {"negative_ndims.mha", header_replaced("NDims = 3", "NDims = -1")},  // ITK read 2^32 values: a hang
      // a file pattern with a step of 0: ITK divided by zero
      {"file_pattern.mha", header_replaced("ElementDataFile = LOCAL", "ElementDataFile = s%d.raw 1 2 0")},
      {"zero_spacing.mha", header_replaced("ElementSpacing = 1 1.25 1.5", "ElementSpacing = 0 1.25 1.5")},
      {"float.mha", header_replaced("MET_INT", "MET_FLOAT")},  // the int bytes read as floats: not whole numbers
      {"nan_sform.nii", nan_sform},
      {"empty.nii.gz", ""},
      {"truncated.nii.gz", nii_gz.substr(0, nii_gz.size() / 2)},
      {"garbage.nii.gz", std::string(400, '\x1f')},
      {"garbage.nrrd", "NRRD0004\ntype: int\ndimension: 3\nsizes: 4 4\nencoding: raw\n\n"},
  };
  for (const auto& c : cases) {
    const fs::path path = write(c.name, c.text);
    try {
      read_label_image(path);
      ADD_FAILURE() << c.name << " was read";
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(c.name), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << c.name << ": " << e.what();
    }
  }
  EXPECT_THROW(read_label_image(scratch("missing.nii.gz")), IoError);
  EXPECT_THROW(read_label_image(scratch("good.png")), InvalidArgument);
}

// Random mutations of a small image in each format (bytes flipped, overwritten, inserted, deleted, the file cut
// short), 400 per format, read under the sanitizers: each is read or refused with a hooke::Error, nothing else (beside
// scripts/fuzz.sh's libFuzzer targets for nii, nii.gz, nrrd and mha, tests/fuzz/itk_clang/README.md). A header
// declaring more voxels than its bytes can hold is refused before ITK allocates (tests/data/images: 4 x 3 x 2 voxels,
// labels 0..2, turned).
TEST(LabelImage, SurvivesMutatedFiles) {
  std::mt19937 rng(20261207);
  for (const char* name : {"seed.nii.gz", "seed.nii", "seed.nrrd", "seed.mha"}) {
    std::string seed;
    {
      std::ifstream in(std::string(HOOKE_TEST_DATA "/images/") + name, std::ios::binary);
      seed.assign(std::istreambuf_iterator<char>(in), {});
    }
    ASSERT_GT(seed.size(), 50u) << name;
    EXPECT_EQ(read_label_image(std::string(HOOKE_TEST_DATA "/images/") + name).voxel_count(), 24) << name;
    int read = 0, refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
      std::string s = seed;
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < edits && !s.empty(); ++e) {
        const std::size_t at = rng() % s.size();
        switch (rng() % 5) {
          case 0: s[at] = static_cast<char>(s[at] ^ (1 << (rng() % 8))); break;
          case 1: s[at] = static_cast<char>(rng()); break;
          case 2: s.insert(at, 1, static_cast<char>(rng())); break;
          case 3: s.erase(at, 1 + rng() % 8); break;
          default: s.resize(at); break;
        }
      }
      const fs::path path = scratch(std::string("mutated_") + name);
      std::ofstream(path, std::ios::binary) << s;
      try {
        read_label_image(path);
        ++read;
      } catch (const Error&) {
        ++refused;
      }
    }
    std::cout << name << ": " << read << " mutated files read, " << refused << " refused\n";
    EXPECT_GT(refused, 0) << name;
  }
}

// The sphere in the box as tets: every tet in a label, each label's tet volume within a few per cent of its voxels'
// (the sphere's interface is resolved by the tets, about 1.3 mm here), and read_mesh takes the image too.
TEST(LabelMesh, EachLabelKeepsItsVolume) {
  const LabelImage img = sphere_in_box();
  LabelMeshOptions o;
  o.tetrahedralize.max_size = 2e-3;
  const LabelMesh m = labels_to_mesh(img, o);
  ASSERT_EQ(m.labels.size(), 2u);
  EXPECT_EQ(m.unlabelled_tets, 0);
  EXPECT_EQ(m.tets.region.size(), m.tets.element_count());
  double total = 0.0, voxels = 0.0;
  for (const LabelReport& r : m.labels) {
    std::cout << "label " << r.label << ": " << r.voxels << " voxels, " << r.tets << " tets, volume error "
              << r.volume_error << ", smallest dihedral " << r.min_dihedral << "\n";
    EXPECT_GT(r.tets, 100);
    EXPECT_LT(std::abs(r.volume_error), 0.05) << r.label;
    total += r.volume;
    voxels += r.voxel_volume;
  }
  EXPECT_NEAR(total, mesh::total_measure(m.tets), 1e-12);
  EXPECT_LT(std::abs(total / voxels - 1.0), 0.02);
  LabelMeshOptions seven;
  seven.labels = {7};
  EXPECT_THROW(labels_to_mesh(img, seven), InvalidArgument);  // no voxel of label 7
  // the same through read_mesh once registered
  register_label_image_reader();
  write_label_image(scratch("box.nrrd"), img);
  const mesh::Mesh read = io::read_mesh(scratch("box.nrrd"));
  EXPECT_EQ(read.kind, mesh::ElementKind::kTet);
  EXPECT_EQ(read.region.maxCoeff(), 2);
  EXPECT_EQ(read.region.minCoeff(), 1);
}

// A real segmentation shipped by Debian (insighttoolkit5-examples: a k-means classification of a T1 MRI of the
// head, 128 x 128 x 62 voxels of 2 x 2 x 3 mm, labels 1..6 with 1 the background class).
TEST(LabelMesh, ARealSegmentationBecomesATwoMaterialModel) {
  const fs::path path =
      "/usr/share/doc/insighttoolkit5-examples/examples/Data/KmeansTest_T1KmeansPrelimSegmentation.nii.gz";
  if (!fs::exists(path)) GTEST_SKIP() << path << " is missing: scripts/setup.sh installs insighttoolkit5-examples";
  const LabelImage img = read_label_image(path);
  EXPECT_EQ(img.size, (std::array<int, 3>{128, 128, 62}));
  EXPECT_LT((img.spacing - Vec3(2e-3, 2e-3, 3e-3)).norm(), 1e-9);
  EXPECT_EQ(img.histogram().size(), 7u);  // 0 .. 6
  LabelMeshOptions o;
  o.labels = {2, 3, 4, 5, 6};
  const LabelMesh m = labels_to_mesh(img, o);
  EXPECT_GT(m.tets.element_count(), 20000);
  for (const LabelReport& r : m.labels) EXPECT_GT(r.tets, 1000) << r.label;
  // grey and white classes (2, 3) soft, the rest 5 times stiffer: calibrated and certified against the FEM of the
  // same regions
  calibrate::ModelOptions mo;
  mo.method = "any-nu-tet";
  mo.regions = {{4, 25000.0, 0.45}, {5, 25000.0, 0.45}, {6, 25000.0, 0.45}};
  const calibrate::CalibratedModel model =
      calibrate::calibrate_model(m.tets, {material::Law::kLinear, 5000.0, 0.45}, mo);
  const auto cases = experiments::certify(model);
  double worst = 0.0;
  for (const auto& c : cases) worst = std::max(worst, c.relative_l2);
  std::cout << m.summary() << "\nworst relative L2 " << worst << "\n";
  EXPECT_LT(worst, 0.15);
}

}  // namespace
}  // namespace hooke::image
