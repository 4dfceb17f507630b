#include "output/output_vtk.hpp"

#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <system_error>

#include "output/atomic_file.hpp"
#include "parallel/comm.hpp"

namespace monosph {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void cannot_write(const fs::path& dir, const std::string& reason) {
  throw InputError("output: cannot write to " + dir.string() + ": " + reason);
}

// vtkErrorCode::GetStringFromErrorCode lives in CommonMisc, which we do not link. Called right
// after the write: errno then holds the reason of a failed write (disk full, file too large).
std::string vtk_error(unsigned long code) {
  switch (code) {
    case vtkErrorCode::CannotOpenFileError:
      return io_error_text("cannot open file");
    case vtkErrorCode::OutOfDiskSpaceError:
      return io_error_text("out of disk space");
    default:
      if (code > 0 && code < vtkErrorCode::FirstVTKErrorCode)
        return std::strerror(static_cast<int>(code));
      return "VTK error " + std::to_string(code);
  }
}

// Shortest text that reads back to the same double.
std::string fmt_double(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof(buf), x);
  return std::string(buf, r.ptr);
}

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      default:
        r += c;
    }
  }
  return r;
}

std::string xml_unescape(std::string s) {
  const std::pair<const char*, char> ents[] = {
      {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}, {"&amp;", '&'}};
  for (auto [e, c] : ents) {
    std::size_t n = std::strlen(e);
    for (std::size_t i = s.find(e); i != std::string::npos; i = s.find(e, i + 1))
      s.replace(i, n, 1, c);
  }
  return s;
}

// Output layout of a field with nc components: out component j takes input component map[j]
// (kZero = 0, kPad = the field's pad_zz). D-vectors pad to 3; DxD and 3x3 column-major tensors
// become 3x3 row-major.
constexpr int kZero = -1, kPad = -2;
template <int D>
std::vector<int> layout(int nc) {
  std::vector<int> m;
  if (nc == D) {
    for (int j = 0; j < 3; ++j) m.push_back(j < D ? j : kZero);
  } else if (nc == D * D) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m.push_back(r < D && c < D ? c * D + r : r == c ? kPad : kZero);
  } else if (nc == 9) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m.push_back(c * 3 + r);
  } else {
    for (int j = 0; j < nc; ++j) m.push_back(j);
  }
  return m;
}

// ParaView's names for the components of a written array (3: X Y Z; 9: XX XY ... ZZ).
std::vector<std::string> component_names(std::size_t n) {
  if (n == 3) return {"X", "Y", "Z"};
  if (n == 9) return {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
  return {};
}

// Copies src into a by `map`; a particle for which `meaningful` is false gets NaN (real arrays).
template <class Arr, class T, class Pred>
void fill(Arr* a, const std::vector<T>& src, int nc, std::size_t n, const std::vector<int>& map,
          double pad, Pred meaningful) {
  const int no = static_cast<int>(map.size());
  a->SetNumberOfComponents(no);
  a->SetNumberOfTuples(static_cast<vtkIdType>(n));
  const auto names = component_names(map.size());
  for (std::size_t j = 0; j < names.size(); ++j)
    a->SetComponentName(static_cast<vtkIdType>(j), names[j].c_str());
  using Out = typename Arr::ValueType;  // long long for vtkTypeInt64Array
  Out* dst = a->GetPointer(0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!meaningful(i)) {
      for (int j = 0; j < no; ++j) dst[i * no + j] = std::numeric_limits<Out>::quiet_NaN();
      continue;
    }
    for (int j = 0; j < no; ++j)
      dst[i * no + j] = map[j] == kZero  ? Out(0)
                        : map[j] == kPad ? static_cast<Out>(pad)
                                         : static_cast<Out>(src[i * nc + map[j]]);
  }
}

template <int D>
void add_array(vtkPointData* pd, const Field& f, std::span<const std::int64_t> phase,
               std::size_t n) {
  auto map = layout<D>(f.ncomp);
  if (f.type == FieldType::Real) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(f.name.c_str());
    fill(a.GetPointer(), f.real, f.ncomp, n, map, f.pad_zz,
         [&](std::size_t i) { return (f.phases >> phase[i]) & 1u; });
    pd->AddArray(a);
  } else {  // integer fields have no "no value"; they are written as they are
    vtkNew<vtkTypeInt64Array> a;
    a->SetName(f.name.c_str());
    fill(a.GetPointer(), f.ints, f.ncomp, n, map, f.pad_zz, [](std::size_t) { return true; });
    pd->AddArray(a);
  }
}

// The parallel file of a frame: array declarations (as in the pieces) and the piece list.
template <int D>
std::string pvtu_text(const Particles<D>& p, const std::vector<int>& ks, const std::string& stem,
                      int ranks) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
       "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PUnstructuredGrid "
       "GhostLevel=\"0\">\n    <PPointData>\n";
  for (int k : ks) {
    const Field& f = p.field(k);
    x << "      <PDataArray type=\"" << (f.type == FieldType::Real ? "Float64" : "Int64")
      << "\" Name=\"" << xml_escape(f.name) << "\" NumberOfComponents=\""
      << layout<D>(f.ncomp).size() << "\"";
    const auto names = component_names(layout<D>(f.ncomp).size());
    for (std::size_t j = 0; j < names.size(); ++j)
      x << " ComponentName" << j << "=\"" << names[j] << "\"";
    x << "/>\n";
  }
  x << "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"Float64\" "
       "NumberOfComponents=\"3\"/>\n    </PPoints>\n";
  for (int r = 0; r < ranks; ++r)
    x << "    <Piece Source=\"" << xml_escape(stem + "_p" + std::to_string(r) + ".vtu") << "\"/>\n";
  x << "  </PUnstructuredGrid>\n</VTKFile>\n";
  return x.str();
}

// Writes grid to path (through path.tmp, renamed when complete); the error ("" if none).
std::string write_grid(vtkUnstructuredGrid* grid, const fs::path& path) {
  const fs::path tmp = temporary_name(path);
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetFileName(tmp.c_str());
  w->SetInputData(grid);
  // Inline base64 binary: the file is well-formed XML. Raw appended data is not, and the
  // ParaView 5.11 of Debian 12 (expat 2.5.0-1+deb12u5, reparse deferral) reads such frames
  // with 0 points.
  w->SetDataModeToBinary();
  w->SetCompressorTypeToZLib();
  w->SetHeaderTypeToUInt64();
  errno = 0;
  if (!w->Write() || w->GetErrorCode() != vtkErrorCode::NoError) {
    const std::string why = vtk_error(w->GetErrorCode());
    std::error_code ec;
    fs::remove(tmp, ec);
    return "output: cannot write " + path.string() + ": " + why;
  }
  try {
    commit_file(tmp, path, false);
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

template <int D>
VtkSeries<D>::VtkSeries(fs::path dir, std::string basename)
    : dir_(std::move(dir)), basename_(std::move(basename)) {
  // VTK's TBB threads would fight the OpenMP threads of the solver for the same cores (measured:
  // a 6x slower run on 2 threads); writing a frame is cheap enough sequentially.
  // (vtkSMPTools.h does not compile as C++20, so the backend is chosen through its variable,
  // read when VTK first uses SMP; a user's own choice is kept.)
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 0);
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) cannot_write(dir_, ec.message());
  if (!fs::is_directory(dir_, ec)) cannot_write(dir_, "not a directory");
  // Probe: really create a file there.
  fs::path probe = dir_ / (".monosph_probe_" + std::to_string(::getpid()));
  std::FILE* fp = std::fopen(probe.c_str(), "w");
  if (!fp) cannot_write(dir_, std::strerror(errno));
  std::fclose(fp);
  fs::remove(probe, ec);
}

template <int D>
fs::path VtkSeries<D>::write(const Particles<D>& p, double time, long step,
                             const std::vector<std::string>& extra_fields) {
  return write(p, p.size(), time, step, extra_fields);
}

template <int D>
fs::path VtkSeries<D>::write(const Particles<D>& p, std::size_t owned, double time, long step,
                             const std::vector<std::string>& extra_fields) {
  const std::size_t n = owned;
  // Fields to write: output ones, then extras (checked first, so nothing is half written).
  std::vector<int> ks;
  for (std::size_t k = 0; k < p.fields().size(); ++k)
    if (p.field(static_cast<int>(k)).output) ks.push_back(static_cast<int>(k));
  for (const auto& name : extra_fields) {
    int k = p.find(name);
    if (k < 0) throw InputError("output: unknown particle field '" + name + "'");
    if (std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
  }

  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  {
    vtkNew<vtkDoubleArray> xyz;
    fill(xyz.GetPointer(), p.field("position").real, D, n, layout<D>(D), 0.0,
         [](std::size_t) { return true; });
    pts->SetData(xyz);
  }
  grid->SetPoints(pts);
  vtkNew<vtkIdTypeArray> conn;
  conn->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i) conn->SetValue(static_cast<vtkIdType>(i), i);
  vtkNew<vtkCellArray> cells;
  cells->SetData(1, conn);
  grid->SetCells(VTK_VERTEX, cells);

  const auto& ph = p.field("phase").ints;
  for (int k : ks) add_array<D>(grid->GetPointData(), p.field(k), ph, n);
  // ParaView picks up "TimeValue" field data as the frame time.
  vtkNew<vtkDoubleArray> tv;
  tv->SetName("TimeValue");
  tv->InsertNextValue(time);
  grid->GetFieldData()->AddArray(tv);
  vtkNew<vtkTypeInt64Array> sv;
  sv->SetName("Step");
  sv->InsertNextValue(step);
  grid->GetFieldData()->AddArray(sv);

  char num[32];
  std::snprintf(num, sizeof(num), "%06ld", step);
  const std::string stem = basename_ + "_" + num;
  const std::string file =
      ranks_ > 1 ? stem + "_p" + std::to_string(rank_) + ".vtu" : stem + ".vtu";
  const fs::path path = dir_ / file;
  std::string err = write_grid(grid, path);
  // Under MPI every rank learns whether all pieces were written before any goes on.
  if (ranks_ > 1) err = Comm::world().first_message(err);
  if (!err.empty()) throw OutputError(err);

  if (ranks_ > 1) {
    // Rank 0 writes the parallel file and the .pvd; every rank learns whether that failed.
    const std::string pfile = stem + ".pvtu";
    std::string perr;
    if (rank_ == 0) {
      try {
        write_file_atomic(dir_ / pfile, pvtu_text<D>(p, ks, stem, ranks_), false);
        std::erase_if(frames_, [&](const Frame& f) { return f.file == pfile || f.time >= time; });
        frames_.push_back({time, pfile});
        write_pvd();
      } catch (const OutputError& e) {
        perr = e.what();
      }
    }
    perr = Comm::world().first_message(perr);
    if (!perr.empty()) throw OutputError(perr);
    return rank_ == 0 ? dir_ / pfile : path;
  }
  // A frame replaces any entry for the same file or a later time (rewrite after a restart).
  std::erase_if(frames_, [&](const Frame& f) { return f.file == file || f.time >= time; });
  frames_.push_back({time, file});
  write_pvd();
  return path;
}

template <int D>
void VtkSeries<D>::write_pvd() const {
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const auto& f : frames_)
    s << "    <DataSet timestep=\"" << fmt_double(f.time) << "\" group=\"\" part=\"0\" file=\""
      << xml_escape(f.file) << "\"/>\n";
  s << "  </Collection>\n</VTKFile>\n";
  write_file_atomic(pvd_path(), s.str(), false);  // a reader never sees half a file
}

template <int D>
int VtkSeries<D>::restore_frames(double restart_time) {
  frames_.clear();
  std::ifstream in(pvd_path());
  if (!in) return 0;
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  static const std::regex tag(R"re(<DataSet\b[^>]*>)re");
  static const std::regex ts(R"re(\btimestep\s*=\s*"([^"]*)")re");
  static const std::regex fl(R"re(\bfile\s*=\s*"([^"]*)")re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), tag); it != std::sregex_iterator();
       ++it) {
    const std::string t = it->str();
    std::smatch mt, mf;
    if (!std::regex_search(t, mt, ts) || !std::regex_search(t, mf, fl)) continue;
    const std::string tstr = mt[1].str();
    double time = 0;
    auto r = std::from_chars(tstr.data(), tstr.data() + tstr.size(), time);
    if (r.ec != std::errc()) continue;
    if (time <= restart_time) frames_.push_back({time, xml_unescape(mf[1].str())});
  }
  std::string err;
  if (rank_ == 0) {
    try {
      write_pvd();
    } catch (const OutputError& e) {
      err = e.what();
    }
  }
  if (ranks_ > 1) err = Comm::world().first_message(err);
  if (!err.empty()) throw OutputError(err);
  return frames();
}

template class VtkSeries<2>;
template class VtkSeries<3>;

}  // namespace monosph
