// VtkSeries: frames read back with VTK's own reader; the .pvd lists every frame.
#include <expat.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "../output_files.hpp"
#include "output/output_vtk.hpp"

namespace monosph {
namespace {
namespace fs = std::filesystem;
using test::file_text;
using test::read_pvd;

// A fresh directory per test, removed afterwards.
struct TmpDir {
  fs::path path;
  explicit TmpDir(const std::string& tag) {
    path = fs::temp_directory_path() / ("monosph_out_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
  }
  ~TmpDir() { fs::remove_all(path); }
};

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& file) {
  vtkNew<vtkXMLGenericDataObjectReader> r;
  r->SetFileName(file.c_str());
  r->Update();
  auto* g = vtkUnstructuredGrid::SafeDownCast(r->GetOutput());
  return g;
}

// Fills p with n particles and a few extra fields of every shape.
template <int D>
void make_particles(Particles<D>& p, std::size_t n) {
  p.append(n);
  p.add_field("stress", D * D, FieldType::Real, true);
  p.add_field("strain3", 9, FieldType::Real, true);
  p.add_field("neighbours", 1, FieldType::Int, true);
  p.add_field("hidden", 1, FieldType::Real, false);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) {
      p.x()[i][d] = 10.0 * i + d;
      p.v()[i][d] = -1.0 * i - d;
    }
    p.rho()[i] = 1000.0 + i;
    p.template view<Mat<D>>("stress")[i] = Mat<D>::Random();
    p.template view<Mat3>("strain3")[i] = Mat3::Random();
    p.template view<std::int64_t>("neighbours")[i] = 3 * i + 7;
    p.template view<double>("hidden")[i] = 0.25 * i;
  }
}

template <int D>
void check_frame(const fs::path& file, Particles<D>& p, bool with_hidden) {
  auto g = read_vtu(file);
  ASSERT_TRUE(g);
  const std::size_t n = p.size();
  ASSERT_EQ(g->GetNumberOfPoints(), static_cast<vtkIdType>(n));
  ASSERT_EQ(g->GetNumberOfCells(), static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(g->GetCellType(i), VTK_VERTEX);
    double x[3];
    g->GetPoint(i, x);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(x[d], d < D ? p.x()[i][d] : 0.0);
  }
  auto* pd = g->GetPointData();
  // Output fields of Particles plus ours; position and mass are not output fields.
  for (const char* name : {"velocity", "density", "pressure", "phase", "body", "id", "stress",
                           "strain3", "neighbours"})
    EXPECT_TRUE(pd->GetArray(name)) << name;
  EXPECT_FALSE(pd->GetArray("position"));
  EXPECT_FALSE(pd->GetArray("mass"));
  EXPECT_EQ(pd->GetArray("hidden") != nullptr, with_hidden);

  auto* vel = pd->GetArray("velocity");
  ASSERT_EQ(vel->GetNumberOfComponents(), 3);
  auto* rho = pd->GetArray("density");
  ASSERT_EQ(rho->GetNumberOfComponents(), 1);
  auto* stress = pd->GetArray("stress");
  ASSERT_EQ(stress->GetNumberOfComponents(), 9);
  auto* strain = pd->GetArray("strain3");
  ASSERT_EQ(strain->GetNumberOfComponents(), 9);
  auto* nb = pd->GetArray("neighbours");
  ASSERT_EQ(nb->GetNumberOfComponents(), 1);
  EXPECT_TRUE(nb->GetDataType() == VTK_LONG || nb->GetDataType() == VTK_LONG_LONG);
  EXPECT_EQ(nb->GetDataTypeSize(), 8);
  auto* id = pd->GetArray("id");
  EXPECT_TRUE(id->GetDataType() == VTK_LONG || id->GetDataType() == VTK_LONG_LONG);
  EXPECT_EQ(id->GetDataTypeSize(), 8);
  EXPECT_EQ(vel->GetDataType(), VTK_DOUBLE);

  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) EXPECT_EQ(vel->GetComponent(i, d), d < D ? p.v()[i][d] : 0.0);
    EXPECT_EQ(rho->GetComponent(i, 0), p.rho()[i]);
    const Mat<D> s = p.template view<Mat<D>>("stress")[i];
    const Mat3 e = p.template view<Mat3>("strain3")[i];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        // Row-major 3x3, zero padded.
        EXPECT_EQ(stress->GetComponent(i, 3 * r + c), r < D && c < D ? s(r, c) : 0.0);
        EXPECT_EQ(strain->GetComponent(i, 3 * r + c), e(r, c));
      }
    EXPECT_EQ(nb->GetComponent(i, 0), 3.0 * i + 7);
    EXPECT_EQ(id->GetComponent(i, 0), static_cast<double>(p.id()[i]));
  }
  auto* tv = g->GetFieldData()->GetArray("TimeValue");
  ASSERT_TRUE(tv);
}

template <int D>
void series_round_trip() {
  TmpDir tmp("series" + std::to_string(D));
  Particles<D> p;
  make_particles(p, 7);
  VtkSeries<D> out(tmp.path / "frames", "run");
  EXPECT_EQ(out.frames(), 0);
  const fs::path f0 = out.write(p, 0.0, 0);
  EXPECT_EQ(f0, tmp.path / "frames" / "run_000000.vtu");
  check_frame(f0, p, false);
  const fs::path f1 = out.write(p, 0.125, 40, {"hidden"});
  EXPECT_EQ(f1.filename(), "run_000040.vtu");
  check_frame(f1, p, true);
  EXPECT_EQ(out.frames(), 2);
  EXPECT_EQ(out.pvd_path(), tmp.path / "frames" / "run.pvd");

  auto entries = read_pvd(out.pvd_path());
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].time, 0.0);
  EXPECT_EQ(entries[1].time, 0.125);
  EXPECT_EQ(entries[0].file, "run_000000.vtu");
  EXPECT_EQ(entries[1].file, "run_000040.vtu");
  for (const auto& e : entries) {
    EXPECT_TRUE(fs::exists(out.pvd_path().parent_path() / e.file));
    auto g = read_vtu(out.pvd_path().parent_path() / e.file);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), e.time);
  }
}

TEST(VtkSeries, RoundTrip2D) {
  series_round_trip<2>();
}
TEST(VtkSeries, RoundTrip3D) {
  series_round_trip<3>();
}

TEST(VtkSeries, EmptyParticleSet) {
  TmpDir tmp("empty");
  Particles<3> p;
  VtkSeries<3> out(tmp.path, "e");
  auto f = out.write(p, 1.0, 1);
  auto g = read_vtu(f);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->GetNumberOfPoints(), 0);
}

TEST(VtkSeries, UnknownExtraFieldThrows) {
  TmpDir tmp("unknown");
  Particles<2> p;
  p.append(3);
  VtkSeries<2> out(tmp.path, "u");
  try {
    out.write(p, 0.0, 0, {"no_such_field"});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_field"), std::string::npos);
  }
  EXPECT_EQ(out.frames(), 0);
}

TEST(VtkSeries, UnwritableDirectoryThrows) {
  TmpDir tmp("unwritable");
  fs::create_directories(tmp.path);
  const fs::path file = tmp.path / "regular_file";
  std::ofstream(file) << "x";
  try {
    VtkSeries<2> out(file / "sub", "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("output: cannot write to"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("regular_file"), std::string::npos);
  }
  EXPECT_THROW(VtkSeries<3>(file, "x"), InputError);
  EXPECT_THROW(VtkSeries<3>("/proc/forbidden", "x"), InputError);
}

TEST(VtkSeries, RestartKeepsEarlierFrames) {
  TmpDir tmp("restart");
  Particles<2> p;
  make_particles(p, 4);
  {
    VtkSeries<2> out(tmp.path, "r");
    for (int k = 0; k < 4; ++k) out.write(p, 0.5 * k, 10 * k);  // t = 0, 0.5, 1, 1.5
  }
  VtkSeries<2> out(tmp.path, "r");
  EXPECT_EQ(out.restore_frames(1.0), 3);  // keeps t = 0, 0.5 and the frame at the restart time
  EXPECT_EQ(out.frames(), 3);
  EXPECT_EQ(read_pvd(out.pvd_path()).size(), 3u);  // rewritten at once
  out.write(p, 1.25, 25);
  auto entries = read_pvd(out.pvd_path());
  ASSERT_EQ(entries.size(), 4u);
  const double times[] = {0.0, 0.5, 1.0, 1.25};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(entries[k].time, times[k]);
  EXPECT_EQ(entries[2].file, "r_000020.vtu");
  EXPECT_EQ(entries[3].file, "r_000025.vtu");

  // Writing the restart frame again replaces its entry (and any later one).
  VtkSeries<2> again(tmp.path, "r");
  EXPECT_EQ(again.restore_frames(1.0), 3);
  again.write(p, 1.0, 20);
  EXPECT_EQ(again.frames(), 3);

  // No .pvd yet: nothing to restore.
  VtkSeries<2> fresh(tmp.path / "fresh", "r");
  EXPECT_EQ(fresh.restore_frames(10.0), 0);
}

TEST(VtkSeries, SameStepReplacesLastEntry) {
  TmpDir tmp("same");
  Particles<2> p;
  p.append(2);
  VtkSeries<2> out(tmp.path, "s");
  out.write(p, 0.0, 0);
  out.write(p, 0.5, 5);
  out.write(p, 0.5, 5);
  EXPECT_EQ(out.frames(), 2);
  EXPECT_EQ(read_pvd(out.pvd_path()).size(), 2u);
}

// Parses the whole file as XML with expat. Debian 12's ParaView 5.11 (expat 2.5.0-1+deb12u5,
// reparse deferral) reads a frame only if the file is well-formed XML: raw appended binary data
// is not, and such frames read back with 0 points there.
std::string xml_error(const fs::path& file) {
  const std::string text = file_text(file);
  XML_Parser parser = XML_ParserCreate(nullptr);
  std::string err;
  if (XML_Parse(parser, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_ERROR)
    err = std::string(XML_ErrorString(XML_GetErrorCode(parser))) + " at line " +
          std::to_string(XML_GetCurrentLineNumber(parser));
  XML_ParserFree(parser);
  return err;
}

template <int D>
void frames_are_well_formed() {
  TmpDir tmp("xml" + std::to_string(D));
  Particles<D> p;
  make_particles(p, 50);
  VtkSeries<D> serial(tmp.path / "serial", "run");
  const fs::path f = serial.write(p, 0.5, 3);
  EXPECT_EQ(xml_error(f), "") << f;
  EXPECT_EQ(xml_error(serial.pvd_path()), "");
  // MPI pieces and the parallel file that lists them.
  VtkSeries<D> mpi(tmp.path / "mpi", "run");
  mpi.set_piece(0, 2);
  const fs::path pf = mpi.write(p, 20, 0.5, 3);
  EXPECT_EQ(pf.extension(), ".pvtu");
  EXPECT_EQ(xml_error(pf), "");
  EXPECT_EQ(xml_error(tmp.path / "mpi" / "run_000003_p0.vtu"), "");
  // Still compressed: 50 particles of random tensors.
  const std::string text = file_text(f);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_EQ(text.find("AppendedData"), std::string::npos);
}

TEST(VtkSeries, FramesAreWellFormedXml2D) {
  frames_are_well_formed<2>();
}
TEST(VtkSeries, FramesAreWellFormedXml3D) {
  frames_are_well_formed<3>();
}

// ParaView's determinant and eigenvalues of a 2D deformation gradient need F_zz = 1; vectors and
// tensors carry component names (also in the .pvtu of an MPI run).
TEST(VtkSeries, TensorComponentsNamedAndPadded2D) {
  TmpDir tmp("tensor");
  Particles<2> p;
  p.append(3);
  const int kF = p.add_field("deformation_gradient", 4, FieldType::Real, true);
  p.field(kF).pad_zz = 1;
  for (std::size_t i = 0; i < 3; ++i) {
    Mat<2> F;
    F << 1.0 + 0.1 * i, 0.2, -0.05, 0.9;
    p.view<Mat<2>>(kF)[i] = F;
  }
  VtkSeries<2> out(tmp.path, "t");
  auto g = read_vtu(out.write(p, 0.0, 0));
  ASSERT_TRUE(g);
  auto* a = g->GetPointData()->GetArray("deformation_gradient");
  ASSERT_TRUE(a);
  ASSERT_EQ(a->GetNumberOfComponents(), 9);
  const char* names[] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
  for (int j = 0; j < 9; ++j) {
    ASSERT_TRUE(a->GetComponentName(j)) << j;
    EXPECT_STREQ(a->GetComponentName(j), names[j]);
  }
  auto* v = g->GetPointData()->GetArray("velocity");
  ASSERT_TRUE(v->GetComponentName(2));
  EXPECT_STREQ(v->GetComponentName(2), "Z");
  for (std::size_t i = 0; i < 3; ++i) {
    Mat3 F3;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) F3(r, c) = a->GetComponent(i, 3 * r + c);
    EXPECT_EQ(F3(2, 2), 1.0);
    EXPECT_EQ(F3(0, 1), 0.2);  // row-major: F_xy
    EXPECT_NEAR(F3.determinant(), p.view<Mat<2>>(kF)[i].determinant(), 1e-15);
  }
  VtkSeries<2> mpi(tmp.path / "mpi", "t");
  mpi.set_piece(0, 2);
  const std::string text = file_text(mpi.write(p, 3, 0.0, 0));
  EXPECT_NE(text.find("Name=\"deformation_gradient\" NumberOfComponents=\"9\" "
                      "ComponentName0=\"XX\""),
            std::string::npos)
      << text;
}

// A field that has no meaning for a phase (a wall's temperature) is NaN there: ParaView shows
// it as "no value" and keeps it out of the colour range.
TEST(VtkSeries, FieldOfOnePhaseIsNaNElsewhere) {
  TmpDir tmp("phase");
  Particles<2> p;
  p.append(4);
  const int kT = p.add_field("temperature", 1, FieldType::Real, true);
  p.field(kT).phases = phase_bit(kSolid);
  for (std::size_t i = 0; i < 4; ++i) {
    p.phase()[i] = i < 2 ? kSolid : kWall;
    p.view<double>(kT)[i] = 293.0 + i;
  }
  VtkSeries<2> out(tmp.path, "p");
  auto g = read_vtu(out.write(p, 0.0, 0));
  ASSERT_TRUE(g);
  auto* t = g->GetPointData()->GetArray("temperature");
  EXPECT_EQ(t->GetComponent(0, 0), 293.0);
  EXPECT_EQ(t->GetComponent(1, 0), 294.0);
  EXPECT_TRUE(std::isnan(t->GetComponent(2, 0)));
  EXPECT_TRUE(std::isnan(t->GetComponent(3, 0)));
  double range[2];
  t->GetRange(range, 0);  // what ParaView colours by
  EXPECT_EQ(range[0], 293.0);
  EXPECT_EQ(range[1], 294.0);
  EXPECT_EQ(g->GetPointData()->GetArray("density")->GetComponent(3, 0), 0.0);  // every phase
}

}  // namespace
}  // namespace monosph
