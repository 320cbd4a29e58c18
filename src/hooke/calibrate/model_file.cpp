#include <algorithm>
#include <cmath>
#include <fstream>
#include <hooke/calibrate/model_file.hpp>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/output_transaction.hpp>
#include <hooke/core/version.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/validate.hpp>
#include <hooke/surface/normal_cone.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace hooke::calibrate {
namespace {

using nlohmann::json;

// ---- writing: the document is built as JSON (the library that reads it) and laid out one row a line

using ordered = nlohmann::ordered_json;

std::string num(double v) { return json(v).dump(); }  // as nlohmann prints a number: the shortest round trip

// A matrix (node coordinates, element indices) as an array of rows.
template <typename Matrix>
ordered rows_of(const Matrix& m) {
  ordered rows = ordered::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    ordered row = ordered::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(i, c));
    rows.push_back(std::move(row));
  }
  return rows;
}

ordered surface_document(const SurfaceTerms& s) {
  ordered out;
  out["scheme"] = s.scheme;
  out["centre"] = {s.centre(0), s.centre(1), s.centre(2)};
  out["anchor_law"] = std::string(surface::anchor_law_name(s.anchor_law));
  ordered anchors = ordered::array();
  for (Eigen::Index i = 0; i < s.k_normal.size(); ++i) {
    ordered row = {s.k_normal(i), s.k_shear(i), s.normals(i, 0), s.normals(i, 1), s.normals(i, 2)};
    // A crease node's normal cone follows its normal; a smooth node's is N N^T and is not written.
    const surface::ConeRow smooth = surface::smooth_cone(s.normals.row(i).transpose());
    if ((s.normal_cones.row(i) - smooth).cwiseAbs().maxCoeff() > 1e-12)
      for (int k = 0; k < 6; ++k) row.push_back(s.normal_cones(i, k));
    anchors.push_back(std::move(row));
  }
  out["anchors"] = std::move(anchors);
  if (!s.volume_penalty) {
    out["volume_penalty"] = nullptr;
    return out;
  }
  ordered penalty;
  penalty["force"] = std::string(surface::volume_force_name(s.volume_force));
  penalty["rest_volume"] = s.rest_volume;
  penalty["bulk_modulus"] = s.bulk_modulus;
  ordered nodes = ordered::array();
  for (Eigen::Index i = 0; i < s.k_bulk.size(); ++i) nodes.push_back({s.k_bulk(i), s.normal_length(i)});
  penalty["nodes"] = std::move(nodes);
  out["volume_penalty"] = std::move(penalty);
  return out;
}

ordered model_document(const CalibratedModel& m) {
  const int d = m.mesh.dim();
  const material::Material& mat = m.material;
  ordered j;
  j["format"] = "hooke-model";
  j["schema_version"] = kModelSchemaVersion;
  j["hooke_version"] = std::string(kVersion);
  j["method"] = m.method;
  j["equation"] = m.equation;
  if (!m.choice.empty()) j["method_choice"] = m.choice;
  if (!m.meshing.empty()) j["meshing"] = m.meshing;
  j["source_mesh"] = m.mesh.source;
  j["units"] = {{"length", "m"}, {"stiffness", "N/m"}, {"mass", "kg"}, {"volume_stiffness", "J"}};
  j["material"] = {{"law", std::string(material::law_name(mat.law))},
                   {"youngs_modulus", mat.youngs_modulus},
                   {"poisson_ratio", mat.poisson_ratio},
                   {"plane", std::string(material::plane_name(mat.plane))},
                   {"thickness", mat.thickness},
                   {"density", m.density}};
  if (!m.regions.empty()) {  // the tissues' own E and nu (docs/regions.md)
    ordered regions = ordered::array();
    for (const RegionMaterial& r : m.regions)
      regions.push_back(
          {{"region", r.region}, {"youngs_modulus", r.youngs_modulus}, {"poisson_ratio", r.poisson_ratio}});
    j["regions"] = std::move(regions);
  }
  j["element_kind"] = std::string(mesh::element_kind_name(m.mesh.kind));
  j["nodes"] = rows_of(m.mesh.nodes);
  j["elements"] = rows_of(m.mesh.elements);
  if (m.mesh.region.size() == m.mesh.element_count() && (m.mesh.region.array() != 0).any()) {
    ordered tags = ordered::array();
    for (Eigen::Index e = 0; e < m.mesh.region.size(); ++e) tags.push_back(m.mesh.region(e));
    j["element_regions"] = std::move(tags);
  }
  ordered masses = ordered::array();
  for (int i = 0; i < m.mesh.node_count(); ++i) masses.push_back(m.masses(d * i));
  j["masses"] = std::move(masses);
  const SpringModel& s = m.springs;
  ordered springs = ordered::array();
  for (size_t k = 0; k < s.pairs.size(); ++k) {
    const auto e = static_cast<Eigen::Index>(k);
    springs.push_back({s.pairs[k][0], s.pairs[k][1], s.stiffness(e), s.rest_length(e)});
  }
  j["springs"] = std::move(springs);
  ordered volume = rows_of(s.volume_tets);
  for (Eigen::Index t = 0; t < s.volume_tets.rows(); ++t) {
    volume[static_cast<size_t>(t)].push_back(s.volume_stiffness(t));
    volume[static_cast<size_t>(t)].push_back(s.rest_volume(t));
  }
  j["volume_terms"] = std::move(volume);
  if (s.spring_exponent != 1.0 || s.volume_exponent != 1.0)  // Hookean springs and quadratic volume terms: no key
    j["term_law"] = {{"spring_exponent", s.spring_exponent}, {"volume_exponent", s.volume_exponent}};
  j["surface"] = m.surface ? surface_document(*m.surface) : ordered(nullptr);
  j["warnings"] = m.warnings;
  ordered certificate = ordered::array();
  for (const CertificateCase& c : m.certificate) {
    ordered one = {{"load", c.load},
                   {"strain", c.strain},
                   {"max_error", c.max_error},
                   {"mean_error", c.mean_error},
                   {"relative_l2", c.relative_l2}};
    if (c.control != "traction" || c.reference != "linear") {  // the small-strain certificate's rows stay as they were
      one["control"] = c.control;
      one["reference"] = c.reference;
      one["force_error"] = c.force_error;
    }
    certificate.push_back(std::move(one));
  }
  j["certificate"] = std::move(certificate);
  return j;
}

// One line: ", " between entries and ": " after keys; numbers and strings as nlohmann prints them.
void write_inline(std::ostream& out, const ordered& v) {
  if (v.is_array()) {
    out << '[';
    for (size_t k = 0; k < v.size(); ++k) {
      if (k) out << ", ";
      write_inline(out, v[k]);
    }
    out << ']';
  } else if (v.is_object()) {
    out << '{';
    bool first = true;
    for (const auto& [key, value] : v.items()) {
      out << (first ? "" : ", ") << json(key).dump() << ": ";
      write_inline(out, value);
      first = false;
    }
    out << '}';
  } else {
    out << v.dump();
  }
}

// A block object (the document, its surface and volume penalty): a key a line at indent + 2; its arrays (but the
// centre) one row a line at indent + 4, every other value on one line.
void write_block(std::ostream& out, const ordered& block, int indent) {
  const std::string pad(static_cast<size_t>(indent + 2), ' ');
  out << "{\n";
  bool first = true;
  for (const auto& [key, value] : block.items()) {
    out << (first ? "" : ",\n") << pad << json(key).dump() << ": ";
    first = false;
    if (value.is_object() && (key == "surface" || key == "volume_penalty")) {
      write_block(out, value, indent + 2);
    } else if (value.is_array() && !value.empty() && key != "centre" && key != "element_regions") {
      out << '[';
      for (size_t k = 0; k < value.size(); ++k) {
        out << (k ? ",\n" : "\n") << pad << "  ";
        write_inline(out, value[k]);
      }
      out << "\n" << pad << ']';
    } else {
      write_inline(out, value);
    }
  }
  out << "\n" << std::string(static_cast<size_t>(indent), ' ') << '}';
}

// ---- reading: every access names the entry it failed on

class Reader {
 public:
  explicit Reader(std::string source) : m_source(std::move(source)) {}
  [[noreturn]] void fail(const std::string& entry, const std::string& why) const {
    throw ParseError::at_entry(m_source, entry, why);
  }
  const json& key(const json& obj, const std::string& where, const char* name) const {
    const auto it = obj.find(name);
    if (it == obj.end()) fail(where.empty() ? name : where, std::string("missing key \"") + name + "\"");
    return *it;
  }
  void only_keys(const json& obj, const std::string& where, std::initializer_list<const char*> allowed) const {
    if (!obj.is_object()) fail(where, "must be an object");
    std::set<std::string> ok(allowed.begin(), allowed.end());
    for (const auto& [k, v] : obj.items())
      if (!ok.count(k)) fail(where.empty() ? k : where + "." + k, "unknown key (schema version 1)");
  }
  double number(const json& v, const std::string& where) const {
    if (!v.is_number()) fail(where, "must be a number, not " + std::string(v.type_name()));
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(where, "is not a finite number");
    return d;
  }
  // A 0-based node index below `nodes`.
  int node(const json& v, const std::string& where, int nodes) const {
    if (!v.is_number_integer()) fail(where, "a node index must be an integer, not " + v.dump());
    const auto i = v.get<std::int64_t>();
    if (i < 0 || i >= nodes)
      fail(where, "node index " + v.dump() + " is out of range (the model has " + std::to_string(nodes) +
                      " nodes, numbered from 0)");
    return static_cast<int>(i);
  }
  std::string string(const json& v, const std::string& where) const {
    if (!v.is_string()) fail(where, "must be a string");
    return v.get<std::string>();
  }
  const json& array(const json& v, const std::string& where, long size = -1) const {
    if (!v.is_array()) fail(where, "must be an array");
    if (size >= 0 && static_cast<long>(v.size()) != size)
      fail(where, "must have " + std::to_string(size) + " entries, not " + std::to_string(v.size()));
    return v;
  }
  static std::string at(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

 private:
  std::string m_source;
};

material::Material read_material(const Reader& r, const json& j, double& density) {
  r.only_keys(j, "material", {"law", "youngs_modulus", "poisson_ratio", "plane", "thickness", "density"});
  material::Material m;
  try {
    m.law = material::law_from_name(r.string(r.key(j, "material", "law"), "material.law"));
  } catch (const InvalidArgument& e) {
    r.fail("material.law", e.what());
  }
  m.youngs_modulus = r.number(r.key(j, "material", "youngs_modulus"), "material.youngs_modulus");
  m.poisson_ratio = r.number(r.key(j, "material", "poisson_ratio"), "material.poisson_ratio");
  try {
    m.plane = material::plane_from_name(r.string(r.key(j, "material", "plane"), "material.plane"));
  } catch (const InvalidArgument&) {
    r.fail("material.plane", "must be \"stress\" or \"strain\"");
  }
  m.thickness = r.number(r.key(j, "material", "thickness"), "material.thickness");
  density = r.number(r.key(j, "material", "density"), "material.density");
  try {
    material::validate(m);
  } catch (const InvalidMaterial& e) {
    r.fail("material", e.what());
  }
  return m;
}

mesh::ElementKind read_kind(const Reader& r, const json& j) {
  const std::string name = r.string(r.key(j, "", "element_kind"), "element_kind");
  for (auto k : {mesh::ElementKind::kTriangle, mesh::ElementKind::kQuad, mesh::ElementKind::kTet,
                 mesh::ElementKind::kSurfaceTriangle})
    if (mesh::element_kind_name(k) == name) return k;
  r.fail("element_kind", "unknown element kind \"" + name + "\" (triangle, quad, tet, surface-triangle)");
}

RowMatX read_points(const Reader& r, const json& j, const char* key, long cols) {
  const json& a = r.array(r.key(j, "", key), key);
  RowMatX out(static_cast<Eigen::Index>(a.size()), cols);
  for (size_t i = 0; i < a.size(); ++i) {
    const json& row = r.array(a[i], Reader::at(key, i), cols);
    for (long c = 0; c < cols; ++c)
      out(static_cast<Eigen::Index>(i), c) = r.number(row[static_cast<size_t>(c)], Reader::at(key, i));
  }
  return out;
}

RowMatXi read_indices(const Reader& r, const json& a, const std::string& key, long cols, int nodes) {
  RowMatXi out(static_cast<Eigen::Index>(a.size()), cols);
  for (size_t i = 0; i < a.size(); ++i) {
    const json& row = r.array(a[i], Reader::at(key, i), cols);
    for (long c = 0; c < cols; ++c)
      out(static_cast<Eigen::Index>(i), c) = r.node(row[static_cast<size_t>(c)], Reader::at(key, i), nodes);
  }
  return out;
}

void read_springs(const Reader& r, const json& j, int nodes, SpringModel& s) {
  const json& a = r.array(r.key(j, "", "springs"), "springs");
  s.pairs.resize(a.size());
  s.stiffness.resize(static_cast<Eigen::Index>(a.size()));
  s.rest_length.resize(static_cast<Eigen::Index>(a.size()));
  for (size_t k = 0; k < a.size(); ++k) {
    const std::string where = Reader::at("springs", k);
    const json& row = r.array(a[k], where, 4);
    for (size_t c = 0; c < 2; ++c) s.pairs[k][c] = r.node(row[c], where, nodes);
    if (s.pairs[k][0] == s.pairs[k][1]) r.fail(where, "a spring needs two different nodes");
    if (s.pairs[k][0] > s.pairs[k][1]) std::swap(s.pairs[k][0], s.pairs[k][1]);
    const double stiffness = r.number(row[2], where), rest = r.number(row[3], where);
    if (stiffness < 0.0) r.fail(where, "stiffness k = " + num(stiffness) + " N/m is negative");
    if (!(rest > 0.0)) r.fail(where, "rest length l0 = " + num(rest) + " m must be > 0");
    s.stiffness(static_cast<Eigen::Index>(k)) = stiffness;
    s.rest_length(static_cast<Eigen::Index>(k)) = rest;
  }
}

// Rows [i, j, k, l, k_V, V0] of tets in 3D, [i, j, k, k_A, A0] of triangles (area terms) in 2D.
void read_volume_terms(const Reader& r, const json& j, int nodes, int dim, SpringModel& s) {
  const json& v = r.array(r.key(j, "", "volume_terms"), "volume_terms");
  const int corners = dim == 2 ? 3 : 4;
  s.volume_tets.resize(static_cast<Eigen::Index>(v.size()), corners);
  s.volume_stiffness.resize(static_cast<Eigen::Index>(v.size()));
  s.rest_volume.resize(static_cast<Eigen::Index>(v.size()));
  for (size_t t = 0; t < v.size(); ++t) {
    const std::string where = Reader::at("volume_terms", t);
    const json& row = r.array(v[t], where, static_cast<size_t>(corners) + 2);
    for (int c = 0; c < corners; ++c)
      s.volume_tets(static_cast<Eigen::Index>(t), c) = r.node(row[static_cast<size_t>(c)], where, nodes);
    s.volume_stiffness(static_cast<Eigen::Index>(t)) = r.number(row[static_cast<size_t>(corners)], where);
    const double v0 = r.number(row[static_cast<size_t>(corners) + 1], where);
    if (!(v0 > 0.0))
      r.fail(where, dim == 2 ? "rest area A0 = " + num(v0) + " m^2 must be > 0"
                             : "rest volume V0 = " + num(v0) + " m^3 must be > 0");
    s.rest_volume(static_cast<Eigen::Index>(t)) = v0;
  }
}

SurfaceTerms read_surface(const Reader& r, const json& j, int nodes) {
  r.only_keys(j, "surface", {"scheme", "centre", "anchor_law", "anchors", "volume_penalty"});
  SurfaceTerms s;
  s.scheme = r.string(r.key(j, "surface", "scheme"), "surface.scheme");
  const json& c = r.array(r.key(j, "surface", "centre"), "surface.centre", 3);
  for (size_t a = 0; a < 3; ++a) s.centre(static_cast<Eigen::Index>(a)) = r.number(c[a], "surface.centre");
  try {
    s.anchor_law = surface::anchor_law_from_name(r.string(r.key(j, "surface", "anchor_law"), "surface.anchor_law"));
  } catch (const InvalidArgument& e) {
    r.fail("surface.anchor_law", e.what());
  }
  const json& a = r.array(r.key(j, "surface", "anchors"), "surface.anchors", nodes);
  s.k_normal.resize(nodes);
  s.k_shear.resize(nodes);
  s.normals.resize(nodes, 3);
  s.normal_cones.resize(nodes, 6);
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string where = Reader::at("surface.anchors", i);
    const json& row = r.array(a[i], where);
    if (row.size() != 5 && row.size() != 11)
      r.fail(where,
             "must have 5 entries (K_E, K_G, normal) or 11 (and a normal cone), not " + std::to_string(row.size()));
    const auto node = static_cast<Eigen::Index>(i);
    s.k_normal(node) = r.number(row[0], where);
    s.k_shear(node) = r.number(row[1], where);
    for (int k = 0; k < 3; ++k) s.normals(node, k) = r.number(row[static_cast<size_t>(2 + k)], where);
    if (row.size() == 11)
      for (int k = 0; k < 6; ++k) s.normal_cones(node, k) = r.number(row[static_cast<size_t>(5 + k)], where);
    else
      s.normal_cones.row(node) = surface::smooth_cone(s.normals.row(node).transpose());
  }
  const json& v = r.key(j, "surface", "volume_penalty");
  s.volume_penalty = !v.is_null();
  if (!s.volume_penalty) return s;
  r.only_keys(v, "surface.volume_penalty", {"force", "rest_volume", "bulk_modulus", "nodes"});
  try {
    s.volume_force = surface::volume_force_from_name(
        r.string(r.key(v, "surface.volume_penalty", "force"), "surface.volume_penalty.force"));
  } catch (const InvalidArgument& e) {
    r.fail("surface.volume_penalty.force", e.what());
  }
  s.rest_volume = r.number(r.key(v, "surface.volume_penalty", "rest_volume"), "surface.volume_penalty.rest_volume");
  s.bulk_modulus = r.number(r.key(v, "surface.volume_penalty", "bulk_modulus"), "surface.volume_penalty.bulk_modulus");
  const json& n = r.array(r.key(v, "surface.volume_penalty", "nodes"), "surface.volume_penalty.nodes", nodes);
  s.k_bulk.resize(nodes);
  s.normal_length.resize(nodes);
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string where = Reader::at("surface.volume_penalty.nodes", i);
    const json& row = r.array(n[i], where, 2);
    s.k_bulk(static_cast<Eigen::Index>(i)) = r.number(row[0], where);
    s.normal_length(static_cast<Eigen::Index>(i)) = r.number(row[1], where);
  }
  return s;
}

std::vector<CertificateCase> read_certificate(const Reader& r, const json& j) {
  std::vector<CertificateCase> out;
  const json& a = r.array(j, "certificate");
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string where = Reader::at("certificate", i);
    r.only_keys(a[i], where,
                {"load", "strain", "max_error", "mean_error", "relative_l2", "control", "reference", "force_error"});
    CertificateCase c;
    if (a[i].contains("control")) c.control = r.string(a[i]["control"], where + ".control");
    if (a[i].contains("reference")) c.reference = r.string(a[i]["reference"], where + ".reference");
    if (a[i].contains("force_error")) c.force_error = r.number(a[i]["force_error"], where + ".force_error");
    c.load = r.string(r.key(a[i], where, "load"), where + ".load");
    c.strain = r.number(r.key(a[i], where, "strain"), where + ".strain");
    c.max_error = r.number(r.key(a[i], where, "max_error"), where + ".max_error");
    c.mean_error = r.number(r.key(a[i], where, "mean_error"), where + ".mean_error");
    c.relative_l2 = r.number(r.key(a[i], where, "relative_l2"), where + ".relative_l2");
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::string model_json(const CalibratedModel& m) {
  validate_model(m, m.mesh.source.empty() ? std::string("the model") : m.mesh.source);
  std::ostringstream out;
  write_block(out, model_document(m), 0);
  out << '\n';
  return out.str();
}

void write_model(const std::filesystem::path& path, const CalibratedModel& m) {
  const std::string ext = path.extension().string();
  if (ext == ".json") {
    const std::string text = model_json(m);
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
    return;
  }
  validate_model(m, m.mesh.source.empty() ? std::string("the model") : m.mesh.source);
  const SpringModel& s = m.springs;
  if (ext == ".csv") {
    write_file_atomically(path, [&](std::ostream& out) {
      out << "i,j,stiffness_n_per_m,rest_length_m\n";
      for (size_t k = 0; k < s.pairs.size(); ++k)
        out << s.pairs[k][0] << ',' << s.pairs[k][1] << ',' << num(s.stiffness(static_cast<Eigen::Index>(k))) << ','
            << num(s.rest_length(static_cast<Eigen::Index>(k))) << '\n';
    });
    return;
  }
  if (ext == ".vtu") {
    const int d = m.mesh.dim();
    VecX node_mass(m.mesh.node_count());
    for (int i = 0; i < m.mesh.node_count(); ++i) node_mass(i) = m.masses(d * i);
    OutputTransaction outputs;  // both files or neither, the springs last
    io::write_vtu(outputs.stage_file(path.parent_path() / (path.stem().string() + "_elements.vtu")), m.mesh,
                  {{"mass", 1, node_mass}});
    io::write_vtu_lines(outputs.stage_file(path), m.mesh.nodes, s.pairs, {{"mass", 1, node_mass}},
                        {{"stiffness", 1, s.stiffness}, {"rest_length", 1, s.rest_length}});
    outputs.commit();
    return;
  }
  throw InvalidArgument("model file '" + path.string() + "': use the extension .json, .vtu or .csv");
}

namespace {
CalibratedModel model_from_json(const json& j, const std::string& source);
}  // namespace

CalibratedModel parse_model(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    const auto byte = std::min<size_t>(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n');
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
    throw ParseError(source, line, "not valid JSON (" + what + ")");
  } catch (const json::exception& e) {  // e.g. a number beyond double's range (found by fuzzing)
    throw ParseError::at_entry(source, "(JSON)", std::string("not valid JSON (") + e.what() + ")");
  }
  try {
    return model_from_json(j, source);
  } catch (const json::exception& e) {  // an access the checks above did not foresee: still the file's fault
    throw ParseError::at_entry(source, "(model)", std::string("malformed (") + e.what() + ")");
  }
}

namespace {

CalibratedModel model_from_json(const json& j, const std::string& source) {
  const Reader r(source);
  if (!j.is_object()) r.fail("(top level)", "a model file is a JSON object");
  if (!j.contains("format") || j["format"] != "hooke-model") r.fail("format", "must be \"hooke-model\"");
  const json& version = r.key(j, "", "schema_version");
  if (!version.is_number_integer() || version.get<std::int64_t>() != kModelSchemaVersion)
    r.fail("schema_version",
           "is " + version.dump() + "; this hooke reads schema version " + std::to_string(kModelSchemaVersion));
  r.only_keys(j, "", {"format",   "schema_version", "hooke_version", "method",         "equation",     "method_choice",
                      "meshing",  "source_mesh",    "units",         "material",       "element_kind", "nodes",
                      "elements", "masses",         "springs",       "volume_terms",   "term_law",     "surface",
                      "warnings", "certificate",    "regions",       "element_regions"});
  if (j.contains("units")) {
    const json& u = j["units"];
    r.only_keys(u, "units", {"length", "stiffness", "mass", "volume_stiffness"});
    const std::pair<const char*, const char*> si[] = {
        {"length", "m"}, {"stiffness", "N/m"}, {"mass", "kg"}, {"volume_stiffness", "J"}};
    for (const auto& [k, unit] : si)
      if (u.contains(k) && u[k] != unit)
        r.fail(std::string("units.") + k, "must be \"" + std::string(unit) + "\" (model files are in SI units)");
  }
  CalibratedModel m;
  m.method = r.string(r.key(j, "", "method"), "method");
  m.equation = j.contains("equation") ? r.string(j["equation"], "equation") : std::string();
  m.choice = j.contains("method_choice") ? r.string(j["method_choice"], "method_choice") : std::string();
  m.meshing = j.contains("meshing") ? r.string(j["meshing"], "meshing") : std::string();
  m.material = read_material(r, r.key(j, "", "material"), m.density);
  const mesh::ElementKind kind = read_kind(r, j);
  RowMatX nodes = read_points(r, j, "nodes", mesh::dimension(kind));
  const int n = static_cast<int>(nodes.rows());
  if (n == 0) r.fail("nodes", "the model has no nodes");
  RowMatXi elements =
      read_indices(r, r.array(r.key(j, "", "elements"), "elements"), "elements", mesh::nodes_per_element(kind), n);
  m.mesh = mesh::make_mesh(kind, std::move(nodes), std::move(elements), source);
  if (j.contains("element_regions")) {
    const json& tags = r.array(j["element_regions"], "element_regions", m.mesh.element_count());
    for (size_t e = 0; e < tags.size(); ++e) {
      if (!tags[e].is_number_integer() || std::abs(tags[e].get<std::int64_t>()) > 2147483647)
        r.fail(Reader::at("element_regions", e), "a region tag must be an integer, not " + tags[e].dump());
      m.mesh.region(static_cast<Eigen::Index>(e)) = static_cast<int>(tags[e].get<std::int64_t>());
    }
  }
  if (j.contains("regions")) {
    const json& regions = r.array(j["regions"], "regions");
    for (size_t k = 0; k < regions.size(); ++k) {
      const std::string at = Reader::at("regions", k);
      r.only_keys(regions[k], at, {"region", "youngs_modulus", "poisson_ratio"});
      const json& tag = r.key(regions[k], at, "region");
      if (!tag.is_number_integer() || std::abs(tag.get<std::int64_t>()) > 2147483647)
        r.fail(at + ".region", "a region tag must be an integer, not " + tag.dump());
      m.regions.push_back({static_cast<int>(tag.get<std::int64_t>()),
                           r.number(r.key(regions[k], at, "youngs_modulus"), at + ".youngs_modulus"),
                           r.number(r.key(regions[k], at, "poisson_ratio"), at + ".poisson_ratio")});
    }
  }
  if (m.mesh.element_count() > 0) mesh::validate(m.mesh, {.fix_orientation = false});  // names the element
  const json& masses = r.array(r.key(j, "", "masses"), "masses", n);
  const int d = mesh::dimension(kind);
  m.masses.resize(d * n);
  for (size_t i = 0; i < masses.size(); ++i) {
    const double mass = r.number(masses[i], Reader::at("masses", i));
    if (!(mass > 0.0)) r.fail(Reader::at("masses", i), "mass " + num(mass) + " kg must be > 0");
    m.masses.segment(d * static_cast<Eigen::Index>(i), d).setConstant(mass);
  }
  read_springs(r, j, n, m.springs);
  read_volume_terms(r, j, n, d, m.springs);
  if (j.contains("term_law")) {
    const json& law = j["term_law"];
    r.only_keys(law, "term_law", {"spring_exponent", "volume_exponent"});
    m.springs.spring_exponent = r.number(r.key(law, "term_law", "spring_exponent"), "term_law.spring_exponent");
    m.springs.volume_exponent = r.number(r.key(law, "term_law", "volume_exponent"), "term_law.volume_exponent");
  }
  if (j.contains("surface") && !j["surface"].is_null()) m.surface = read_surface(r, j["surface"], n);
  if (j.contains("warnings")) {
    const json& w = r.array(j["warnings"], "warnings");
    for (size_t i = 0; i < w.size(); ++i) m.warnings.push_back(r.string(w[i], Reader::at("warnings", i)));
  }
  if (j.contains("certificate")) m.certificate = read_certificate(r, j["certificate"]);
  validate_model(m, [&](const std::string& entry, const std::string& why) { r.fail(entry, why); });
  return m;
}

}  // namespace

CalibratedModel read_model(const std::filesystem::path& path) {
  if (path.extension() != ".json")
    throw InvalidArgument("'" + path.string() + "': models are read from .json files (the .vtu and .csv are exports)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open model file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw IoError("failed while reading '" + path.string() + "'");
  return parse_model(text.str(), path.string());
}

}  // namespace hooke::calibrate
