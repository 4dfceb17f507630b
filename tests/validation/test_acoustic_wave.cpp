// cases/acoustic_wave: frequency c k within 1 %, mass exact, momentum to 1e-12; VTK read-back;
// restart from a checkpoint reproduces the uninterrupted run.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <regex>

#include "run_helpers.hpp"

using namespace monosph::test;

TEST(AcousticWave, FrequencyMassAndMomentum) {
  const std::string out = out_dir("acoustic_wave");
  auto r =
      run_monosph("run " + source("cases/acoustic_wave/scene.yaml") + " --out " + out + " --quiet");
  ASSERT_EQ(r.code, 0) << r.output;
  auto js = summary(out);
  EXPECT_EQ(js["status"], "completed");
  const double err = js["metrics"]["angular_frequency"]["relative_error"].get<double>();
  EXPECT_LT(err, 0.01);
  auto t = read_csv(out + "/probes.csv");
  const auto& mass = t["mass"];
  for (double m : mass) EXPECT_EQ(m, mass.front());
  double pmax = 0, scale = 0;
  for (std::size_t k = 0; k < mass.size(); ++k) {
    pmax = std::max({pmax, std::abs(t["momentum_x"][k]), std::abs(t["momentum_y"][k])});
    scale = std::max(scale, t["momentum_scale"][k]);
  }
  EXPECT_GT(scale, 0);
  EXPECT_LT(pmax, 1e-12 * scale);
  // ParaView files: read every frame of the .pvd back with VTK's reader.
  std::ifstream pvd(out + "/acoustic_wave.pvd");
  std::stringstream ss;
  ss << pvd.rdbuf();
  std::regex file_re("file=\"([^\"]+)\"");
  int frames = 0;
  std::string text = ss.str();
  for (std::sregex_iterator it(text.begin(), text.end(), file_re), end; it != end; ++it) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((out + "/" + (*it)[1].str()).c_str());
    reader->Update();
    auto* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), js["particles"].get<long>());
    for (const char* name : {"velocity", "density", "pressure", "id", "density_rate"})
      EXPECT_NE(grid->GetPointData()->GetArray(name), nullptr) << name;
    EXPECT_EQ(grid->GetPointData()->GetArray("velocity")->GetNumberOfComponents(), 3);
    ++frames;
  }
  EXPECT_GE(frames, 50);
}

TEST(AcousticWave, RestartEqualsUninterruptedRun) {
  const std::string scene = source("cases/acoustic_wave/scene.yaml");
  const std::string full = out_dir("restart_full"), half = out_dir("restart_half");
  const std::string opts = " --set end_time=0.006 output.checkpoint_every=0.003 --quiet";
  ASSERT_EQ(run_monosph("run " + scene + " --out " + full + opts).code, 0);
  auto a = run_monosph("run " + scene + " --out " + half +
                       " --set end_time=0.003 output.checkpoint_every=0.003 --quiet");
  ASSERT_EQ(a.code, 0) << a.output;
  auto b = run_monosph("run --restart " + half + "/final.h5 --out " + half +
                       " --set end_time=0.006 --quiet");
  ASSERT_EQ(b.code, 0) << b.output;
  expect_same_checkpoint(full + "/final.h5", half + "/final.h5");
  // The probe series continues where it stopped: same rows as the full run.
  auto ta = read_csv(full + "/probes.csv"), tb = read_csv(half + "/probes.csv");
  EXPECT_EQ(ta["time"], tb["time"]);
  EXPECT_EQ(ta["mode"], tb["mode"]);
}
