#include "mdem/output.hpp"

#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "common/csv.hpp"
#include "common/atomic_file.hpp"
#include "common/errors.hpp"

namespace mesochain::mdem {

std::vector<std::string> energyColumns(const EnergyLedger& layout) {
  std::vector<std::string> c;
  for (const LedgerEntry& e : layout.entries())
    if (e.kind != EnergyKind::Dissipated) c.push_back(e.name);
  c.push_back("");
  for (const LedgerEntry& e : layout.entries())
    if (e.kind == EnergyKind::Dissipated) c.push_back(e.name);
  return c;
}

EnergyCsvWriter::EnergyCsvWriter(const std::string& path, const EnergyLedger& layout, std::vector<int> probes,
                                 std::int64_t resumeAt)
    : out_(path, resumeAt), columns_(energyColumns(layout)), probes_(std::move(probes)) {
  if (out_.resumed()) return;
  std::string h = "step,time_ns";
  for (const std::string& c : columns_) h += "," + csvField((c.empty() ? std::string("total") : c) + "_zJ");
  for (int p : probes_)
    for (const char* c : {"ux_nm", "uy_nm", "uz_nm", "rx_rad", "ry_rad", "rz_rad"}) h += fmt::format(",p{}_{}", p, c);
  out_.write(h + "\n");
}

void EnergyCsvWriter::write(long step, double time, const EnergyLedger& e, const Bodies& b) {
  std::string row = fmt::format("{},{:.10g}", step, time);
  for (const std::string& c : columns_) row += fmt::format(",{:.12g}", c.empty() ? e.total() : e[c]);
  for (int p : probes_) {
    const Vec3 u = b.position[p] - b.initialPosition[p];
    const Vec3& r = b.accumulatedRotation[p];
    row += fmt::format(",{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}", u.x(), u.y(), u.z(), r.x(), r.y(), r.z());
  }
  out_.write(row + "\n");
}

void writeXyzFrame(std::ostream& out, const Bodies& b, const std::vector<ElementType>& types,
                   double time, long step) {
  // Extended XYZ as ASE (ase.io.read) and OVITO read it: `species` must be a chemical symbol, so
  // every element is the placeholder C (carbon filaments) and its element type is the column
  // type_name (and its index, type_id, for tools that take numeric columns only); the comment
  // line states the units (mDEM's system, docs/mdem-units.md).
  out << b.size() << "\n";
  out << "Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:velo:R:3:type_name:S:1:type_id:I:1"
      << fmt::format(" Time={:.10g} Step={} pbc=\"F F F\"", time, step)
      << " units=\"pos:nm velo:nm/ns Time:ns aspherical_shape:nm(half-extents) orientation:quaternion(x,y,z,w)\"\n";
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = types[b.type[i]];
    const Vec3& x = b.position[i];
    const Quat& q = b.orientation[i];
    const Vec3 e = t.halfExtents();
    const Vec3& v = b.velocity[i];
    out << fmt::format("C {:.10g} {:.10g} {:.10g} {:.12g} {:.12g} {:.12g} {:.12g} {:.6g} {:.6g} "
                       "{:.6g} {:.8g} {:.8g} {:.8g} {} {}\n",
                       x.x(), x.y(), x.z(), q.x, q.y, q.z, q.w, e.x(), e.y(), e.z(),
                       v.x(), v.y(), v.z(), t.name, b.type[i]);
  }
}

void writeVtkFrame(const std::string& path, const Bodies& b, const std::vector<Bond>& bonds,
                   double time, const VtkFields& fields) {
  AtomicOutputFile file(path);  // a kill leaves the previous frame or none, never half of one
  std::ofstream& out = file.stream();
  const int n = b.size();
  out << "# vtk DataFile Version 3.0\n";
  out << fmt::format("mesochain mdem frame, time {:.10g} ns, lengths in nm\n", time);
  out << "ASCII\nDATASET POLYDATA\n";
  out << "POINTS " << n << " double\n";
  for (const Vec3& x : b.position) out << fmt::format("{:.10g} {:.10g} {:.10g}\n", x.x(), x.y(), x.z());
  out << "VERTICES " << n << " " << 2 * n << "\n";
  for (int i = 0; i < n; ++i) out << "1 " << i << "\n";
  if (!bonds.empty()) {
    out << "LINES " << bonds.size() << " " << 3 * bonds.size() << "\n";
    for (const Bond& bd : bonds) out << "2 " << bd.a << " " << bd.b << "\n";
  }
  out << "POINT_DATA " << n << "\n";
  out << "SCALARS id int 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) out << i << "\n";
  out << "SCALARS type int 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) out << b.type[i] << "\n";
  out << "SCALARS quaternion double 4\nLOOKUP_TABLE default\n";
  for (const Quat& q : b.orientation) out << fmt::format("{:.12g} {:.12g} {:.12g} {:.12g}\n", q.w, q.x, q.y, q.z);
  const char* names[3] = {"axis_x", "axis_y", "axis_z"};
  for (int a = 0; a < 3; ++a) {
    out << "VECTORS " << names[a] << " double\n";
    for (const Quat& q : b.orientation) {
      const Vec3 e = rotate(q, Vec3::Unit(a));
      out << fmt::format("{:.10g} {:.10g} {:.10g}\n", e.x(), e.y(), e.z());
    }
  }
  out << "VECTORS velocity double\n";
  for (const Vec3& v : b.velocity) out << fmt::format("{:.10g} {:.10g} {:.10g}\n", v.x(), v.y(), v.z());
  if (static_cast<int>(fields.halfExtents.size()) == n) {
    out << "VECTORS half_extents_nm double\n";
    for (const Vec3& e : fields.halfExtents) out << fmt::format("{:.10g} {:.10g} {:.10g}\n", e.x(), e.y(), e.z());
  }
  if (static_cast<int>(fields.shape.size()) == n) {
    out << "SCALARS shape int 1\nLOOKUP_TABLE default\n";
    for (int sh : fields.shape) out << sh << "\n";
  }
  if (static_cast<int>(fields.elementEnergy.size()) == n) {
    out << "SCALARS energy_zJ double 1\nLOOKUP_TABLE default\n";
    for (double e : fields.elementEnergy) out << fmt::format("{:.10g}\n", e);
  }
  if (!bonds.empty() && fields.bondLoads.size() == bonds.size()) {
    out << "CELL_DATA " << n + bonds.size() << "\n";
    const char* names[4] = {"normal_force_pN", "shear_force_pN", "bending_moment_pN_nm", "twisting_moment_pN_nm"};
    for (int q = 0; q < 4; ++q) {
      out << "SCALARS " << names[q] << " double 1\nLOOKUP_TABLE default\n";
      for (int i = 0; i < n; ++i) out << "0\n";  // the vertex cells
      for (const BondLoad& l : fields.bondLoads) {
        const double v[4] = {l.normalForce, l.shearForce, l.bendingMoment, l.twistingMoment};
        out << fmt::format("{:.10g}\n", v[q]);
      }
    }
  }
  file.commit();
}

namespace {
std::string xmlAttribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}
}  // namespace

double vtkFrameTime(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line), std::getline(in, line);  // the version line, then the title
  static const std::regex time(R"(time ([-+0-9.eE]+) ns)");
  std::smatch m;
  if (!std::regex_search(line, m, time))
    throw InputError(path, "line 2", "\"" + line + "\"", "a mesochain VTK frame title with \"time T ns\"");
  return std::stod(m[1].str());
}

VtkSeries::VtkSeries(std::string prefix, long existingFrames) : path_(prefix + ".pvd") {
  for (long k = 0; k < existingFrames; ++k) {
    const std::string frame = fmt::format("{}_{:06d}.vtk", prefix, k);
    std::error_code ec;
    if (std::filesystem::exists(frame, ec))
      frames_.emplace_back(vtkFrameTime(frame), std::filesystem::path(frame).filename().string());
  }
}

void VtkSeries::add(const std::string& framePath, double time) {
  frames_.emplace_back(time, std::filesystem::path(framePath).filename().string());
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<!-- mesochain mdem frames; timestep = simulation time in ns -->\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, file] : frames_)
    xml += fmt::format("    <DataSet timestep=\"{:.10g}\" part=\"0\" file=\"{}\"/>\n", t, xmlAttribute(file));
  xml += "  </Collection>\n</VTKFile>\n";
  writeFileAtomically(path_, xml);
}

}  // namespace mesochain::mdem
