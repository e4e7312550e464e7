#include "mdem/output.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

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
  for (const std::string& c : columns_) h += "," + (c.empty() ? std::string("total") : c) + "_zJ";
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
  out << b.size() << "\n";
  out << "Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:velo:R:3"
      << fmt::format(" Time={:.10g} Step={} pbc=\"F F F\"\n", time, step);
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = types[b.type[i]];
    const Vec3& x = b.position[i];
    const Quat& q = b.orientation[i];
    const Vec3 e = t.halfExtents();
    const Vec3& v = b.velocity[i];
    out << fmt::format("{} {:.10g} {:.10g} {:.10g} {:.12g} {:.12g} {:.12g} {:.12g} {:.6g} {:.6g} "
                       "{:.6g} {:.8g} {:.8g} {:.8g}\n",
                       t.name, x.x(), x.y(), x.z(), q.x, q.y, q.z, q.w, e.x(), e.y(), e.z(),
                       v.x(), v.y(), v.z());
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

}  // namespace mesochain::mdem
