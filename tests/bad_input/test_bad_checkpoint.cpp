// Damaged and forged checkpoints (`run --restart`): exit code 2 and one line naming the file and
// what is wrong (dataset, particle); never a crash, a hang, or a run that goes on from bad data.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "fault_helpers.hpp"

using namespace monosph::test;
namespace fs = std::filesystem;

namespace {

// Edits a checkpoint in place with the HDF5 C API (checksums are recomputed on write, so what
// is forged here must be caught by the reader's own checks).
class H5Edit {
 public:
  explicit H5Edit(const std::string& file) : f_(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
    EXPECT_GE(f_, 0) << file;
  }
  ~H5Edit() { H5Fclose(f_); }
  H5Edit(const H5Edit&) = delete;
  H5Edit& operator=(const H5Edit&) = delete;

  // One element (row, col) of a 2-D dataset (1-D: col 0).
  void set(const char* dset, hsize_t row, hsize_t col, double v) { put(dset, row, col, &v, true); }
  void set_int(const char* dset, hsize_t row, std::int64_t v) { put(dset, row, 0, &v, false); }
  void set_attr(const char* obj, const char* name, double v) {
    attr(obj, name, H5T_NATIVE_DOUBLE, &v);
  }
  void set_attr_int(const char* obj, const char* name, std::int64_t v) {
    attr(obj, name, H5T_NATIVE_INT64, &v);
  }
  // The value of a named module scalar (/meta/scalar_names, /meta/scalar_values).
  void set_scalar(const std::string& name, double v) {
    hid_t d = H5Dopen2(f_, "/meta/scalar_names", H5P_DEFAULT);
    hid_t t = H5Dget_type(d), sp = H5Dget_space(d);
    const std::size_t len = H5Tget_size(t);
    const hssize_t n = H5Sget_simple_extent_npoints(sp);
    std::vector<char> buf(n * len);
    H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
    H5Sclose(sp), H5Tclose(t), H5Dclose(d);
    for (hssize_t i = 0; i < n; ++i)
      if (std::string(&buf[i * len], strnlen(&buf[i * len], len)) == name)
        return put("/meta/scalar_values", static_cast<hsize_t>(i), 0, &v, true);
    ADD_FAILURE() << "no scalar " << name;
  }
  void remove(const char* path) { EXPECT_GE(H5Ldelete(f_, path, H5P_DEFAULT), 0) << path; }
  // Replaces a field by one of `rows` rows (same attributes).
  void resize_field(const char* dset, hsize_t rows) {
    remove(dset);
    hsize_t dims[2] = {rows, 1};
    hid_t sp = H5Screate_simple(2, dims, nullptr);
    hid_t d = H5Dcreate2(f_, dset, H5T_IEEE_F64LE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> v(rows, 1.0);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Sclose(sp), H5Dclose(d);
    set_attr_int(dset, "ncomp", 1);
    set_attr_int(dset, "output", 0);
  }
  // Rewrites a field as the writer did before the checksums: contiguous, no filter.
  void make_contiguous(const std::string& dset) {
    hid_t d = H5Dopen2(f_, dset.c_str(), H5P_DEFAULT);
    hid_t t = H5Dget_type(d), sp = H5Dget_space(d);
    std::vector<char> buf(H5Sget_simple_extent_npoints(sp) * H5Tget_size(t));
    H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
    std::int64_t ncomp = 0, output = 0;
    auto get = [&](const char* name, std::int64_t* v) {
      hid_t a = H5Aopen(d, name, H5P_DEFAULT);
      H5Aread(a, H5T_NATIVE_INT64, v);
      H5Aclose(a);
    };
    get("ncomp", &ncomp), get("output", &output);
    H5Dclose(d);
    remove(dset.c_str());
    d = H5Dcreate2(f_, dset.c_str(), t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()), 0) << dset;
    H5Dclose(d), H5Sclose(sp), H5Tclose(t);
    set_attr_int(dset.c_str(), "ncomp", ncomp);
    set_attr_int(dset.c_str(), "output", output);
  }
  // The names in /fields.
  std::vector<std::string> fields() {
    std::vector<std::string> names;
    hid_t g = H5Gopen2(f_, "/fields", H5P_DEFAULT);
    H5Literate(
        g, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr,
        [](hid_t, const char* name, const H5L_info_t*, void* v) -> herr_t {
          static_cast<std::vector<std::string>*>(v)->push_back(name);
          return 0;
        },
        &names);
    H5Gclose(g);
    return names;
  }
  // File offset of a dataset's first data byte (contiguous, or its first chunk).
  haddr_t data_offset(const char* dset) {
    hid_t d = H5Dopen2(f_, dset, H5P_DEFAULT);
    hid_t pl = H5Dget_create_plist(d);
    haddr_t addr = HADDR_UNDEF;
    if (H5Pget_layout(pl) == H5D_CHUNKED) {
      hid_t sp = H5Dget_space(d);
      hsize_t off[2];
      unsigned mask = 0;
      hsize_t size = 0;
      H5Dget_chunk_info(d, sp, 0, off, &mask, &addr, &size);
      H5Sclose(sp);
    } else {
      addr = H5Dget_offset(d);
    }
    H5Pclose(pl), H5Dclose(d);
    EXPECT_NE(addr, HADDR_UNDEF) << dset;
    return addr;
  }

 private:
  void put(const char* dset, hsize_t row, hsize_t col, const void* v, bool real) {
    hid_t d = H5Dopen2(f_, dset, H5P_DEFAULT);
    ASSERT_GE(d, 0) << dset;
    hid_t sp = H5Dget_space(d);
    const int nd = H5Sget_simple_extent_ndims(sp);
    const hsize_t start[2] = {row, col}, one[2] = {1, 1};
    H5Sselect_hyperslab(sp, H5S_SELECT_SET, start, nullptr, one, nullptr);
    hid_t mem = H5Screate_simple(nd, one, nullptr);
    EXPECT_GE(H5Dwrite(d, real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, mem, sp, H5P_DEFAULT, v), 0)
        << dset;
    H5Sclose(mem), H5Sclose(sp), H5Dclose(d);
  }
  // Writes (or creates) a scalar attribute of a 64-bit type like `type`.
  void attr(const char* obj, const char* name, hid_t type, const void* v) {
    hid_t o = H5Oopen(f_, obj, H5P_DEFAULT);
    ASSERT_GE(o, 0) << obj;
    hid_t a = H5Aexists(o, name) > 0 ? H5Aopen(o, name, H5P_DEFAULT) : -1;
    if (a < 0) {
      hid_t sp = H5Screate(H5S_SCALAR);
      a = H5Acreate2(o, name, type == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : H5T_STD_I64LE, sp,
                     H5P_DEFAULT, H5P_DEFAULT);
      H5Sclose(sp);
    }
    EXPECT_GE(a, 0) << obj << " " << name;
    EXPECT_GE(H5Awrite(a, type, v), 0) << obj << " " << name;
    H5Aclose(a), H5Oclose(o);
  }
  hid_t f_;
};

// Flips n bytes of the file from offset on.
void flip_bytes(const std::string& file, std::uint64_t offset, int n) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(static_cast<std::streamoff>(offset));
  std::vector<char> b(n);
  f.read(b.data(), n);
  for (char& c : b) c = static_cast<char>(~c);
  f.seekp(static_cast<std::streamoff>(offset));
  f.write(b.data(), n);
}

void flip_field(const std::string& file, const char* dset, int n) {
  haddr_t at;
  {
    H5Edit e(file);
    at = e.data_offset(dset);
  }
  flip_bytes(file, at + 64, n);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Case {
  const char* name;
  std::function<void(const std::string& file)> damage;
  std::vector<std::string> message;  // besides the file name
};

// Each case damages the final.h5 of a 3-step run of tests/scenes/grain_bounce.yaml (a solid block
// with fixed rows, a rigid grain: two materials, two bodies, a cluster, a contact law).
const Case kCases[] = {
    {"material_1e6",
     [](auto f) { H5Edit(f).set_int("/fields/material", 7, 1000000); },
     {"material", "1000000"}},
    {"material_negative",
     [](auto f) { H5Edit(f).set_int("/fields/material", 3, -1); },
     {"material", "-1"}},
    {"body_99", [](auto f) { H5Edit(f).set_int("/fields/body", 5, 99); }, {"body", "99"}},
    {"body_negative", [](auto f) { H5Edit(f).set_int("/fields/body", 5, -3); }, {"body", "-3"}},
    {"phase_99", [](auto f) { H5Edit(f).set_int("/fields/phase", 9, 99); }, {"phase", "99"}},
    {"phase_negative", [](auto f) { H5Edit(f).set_int("/fields/phase", 9, -1); }, {"phase"}},
    {"cluster_99", [](auto f) { H5Edit(f).set_int("/fields/cluster", 11, 99); }, {"cluster", "99"}},
    {"cluster_below_minus_one",
     [](auto f) { H5Edit(f).set_int("/fields/cluster", 2, -7); },
     {"cluster", "-7"}},
    {"boundary_99",
     [](auto f) { H5Edit(f).set_int("/fields/boundary", 2, 99); },
     {"boundary", "99"}},
    {"id_negative", [](auto f) { H5Edit(f).set_int("/fields/id", 4, -5); }, {"id", "-5"}},
    {"id_beyond_next_id", [](auto f) { H5Edit(f).set_int("/fields/id", 4, 1L << 40); }, {"id"}},
    {"id_twice",
     [](auto f) {
       H5Edit e(f);
       e.set_int("/fields/id", 4, 7), e.set_int("/fields/id", 5, 7);
     },
     {"id", "7"}},
    {"velocity_nan",
     [](auto f) { H5Edit(f).set("/fields/velocity", 6, 1, kNaN); },
     {"velocity", "non-finite"}},
    {"density_inf",
     [](auto f) { H5Edit(f).set("/fields/density", 6, 0, kInf); },
     {"density", "non-finite"}},
    {"position_nan",
     [](auto f) { H5Edit(f).set("/fields/position", 0, 0, kNaN); },
     {"position", "non-finite"}},
    // 1 km outside a 4 cm domain: the restart's first rebuild stopped with exit 3 and left only
    // .lock (no frame, no summary).
    {"position_outside_domain",
     [](auto f) { H5Edit(f).set("/fields/position", 5, 1, 1000.0); },
     {"field 'position', particle 5", "y = 1000 lies outside the domain [-0.001, 0.03]",
      "damaged"}},
    {"build_position_outside_domain",
     [](auto f) { H5Edit(f).set("/fields/build_position", 5, 0, -1000.0); },
     {"field 'build_position', particle 5", "x = -1000 lies outside the domain [0, 0.04]"}},
    {"mass_minus_inf",
     [](auto f) { H5Edit(f).set("/fields/mass", 1, 0, -kInf); },
     {"mass", "non-finite"}},
    // Fletcher-32 sums 16-bit words modulo 65535, so a zero word flipped to 0xffff goes unseen:
    // the velocity of the fixed rows (zero) then reads as NaN, which the finite check rejects.
    {"velocity_64_flipped_bytes",
     [](auto f) { flip_field(f, "/fields/velocity", 64); },
     {"velocity"}},
    {"position_64_flipped_bytes",
     [](auto f) { flip_field(f, "/fields/position", 64); },
     {"position", "checksum"}},
    {"density_1_flipped_byte",
     [](auto f) { flip_field(f, "/fields/density", 1); },
     {"density", "checksum"}},
    {"material_64_flipped_bytes",
     [](auto f) { flip_field(f, "/fields/material", 64); },
     {"material", "checksum"}},
    {"scene_text_flipped_bytes",
     [](auto f) { flip_field(f, "/meta/scene_yaml", 16); },
     {"scene_yaml", "checksum"}},
    {"truncated_half", [](auto f) { fs::resize_file(f, fs::file_size(f) / 2); }, {}},
    {"truncated_to_zero", [](auto f) { fs::resize_file(f, 0); }, {"not a monosph checkpoint"}},
    {"not_hdf5",
     [](auto f) { std::ofstream(f) << "dimension: 2\n"; },
     {"not a monosph checkpoint"}},
    {"missing_density", [](auto f) { H5Edit(f).remove("/fields/density"); }, {"density"}},
    {"missing_position", [](auto f) { H5Edit(f).remove("/fields/position"); }, {"position"}},
    {"missing_meta", [](auto f) { H5Edit(f).remove("/meta"); }, {"meta"}},
    {"missing_scene_text", [](auto f) { H5Edit(f).remove("/meta/scene_yaml"); }, {"scene_yaml"}},
    {"density_row_count",
     [](auto f) { H5Edit(f).resize_field("/fields/density", 10); },
     {"density", "particle count"}},
    {"velocity_ncomp",
     [](auto f) { H5Edit(f).set_attr_int("/fields/velocity", "ncomp", 3); },
     {"velocity", "shape"}},
    {"time_nan", [](auto f) { H5Edit(f).set_attr("/meta", "time", kNaN); }, {"time"}},
    {"dt_negative", [](auto f) { H5Edit(f).set_attr("/meta", "dt", -1.0); }, {"dt"}},
    {"step_negative", [](auto f) { H5Edit(f).set_attr_int("/meta", "step", -4); }, {"step"}},
    {"next_id_negative",
     [](auto f) { H5Edit(f).set_attr_int("/meta", "next_id", -1); },
     {"next_id"}},
    {"dimension_5", [](auto f) { H5Edit(f).set_attr_int("/meta", "dimension", 5); }, {"dimension"}},
    {"version_99", [](auto f) { H5Edit(f).set_attr_int("/", "version", 99); }, {"version"}},
    {"scalar_nan", [](auto f) { H5Edit(f).set_scalar("next_output", kNaN); }, {"next_output"}},
    {"cluster_count_huge",
     [](auto f) { H5Edit(f).set_scalar("clusters.count", 1e18); },
     {"clusters.count"}},
    {"cluster_count_nan",
     [](auto f) { H5Edit(f).set_scalar("clusters.count", kNaN); },
     {"clusters.count"}},
    {"a_directory",
     [](auto f) {
       fs::remove(f);
       fs::create_directories(fs::path(f) / "x");
     },
     {"not a regular file"}},
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

}  // namespace

class BadCheckpoint : public ::testing::TestWithParam<Case> {};

TEST_P(BadCheckpoint, ExitsWithCode2AndNamesTheFile) {
  const Case& c = GetParam();
  const std::string src = out_dir(std::string("bad_ckpt_src_") + c.name);
  auto made = run_limited("run " + source("tests/scenes/grain_bounce.yaml") + " --out " + src +
                          " --steps 3");
  ASSERT_EQ(made.code, 0) << made.output;
  const std::string file = src + "/final.h5";
  c.damage(file);

  const std::string out = out_dir(std::string("bad_ckpt_run_") + c.name);
  auto r = run_limited("run --restart " + file + " --out " + out + " --steps 2");
  auto parts = c.message;
  parts.push_back(file);
  expect_clean_failure(r, 2, parts);
  if (fs::exists(out)) {
    expect_nothing_claims_success(out);
  }
}

INSTANTIATE_TEST_SUITE_P(Damaged, BadCheckpoint, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The undamaged checkpoint restarts (the cases above fail for their damage, not for the setup).
TEST(BadCheckpoint, UndamagedCheckpointRestarts) {
  const std::string src = out_dir("bad_ckpt_src_undamaged");
  ASSERT_EQ(run_limited("run " + source("tests/scenes/grain_bounce.yaml") + " --out " + src +
                        " --steps 3")
                .code,
            0);
  const std::string out = out_dir("bad_ckpt_run_undamaged");
  auto r = run_limited("run --restart " + src + "/final.h5 --out " + out + " --steps 2");
  EXPECT_EQ(r.code, 0) << r.output;
}

// A checkpoint written before the checksums (contiguous fields, no filter) still restarts, and
// the same run from it ends in the same state.
TEST(BadCheckpoint, CheckpointWithoutChecksumsRestarts) {
  const std::string src = out_dir("bad_ckpt_src_unchecked");
  ASSERT_EQ(run_limited("run " + source("tests/scenes/grain_bounce.yaml") + " --out " + src +
                        " --steps 3")
                .code,
            0);
  fs::copy_file(src + "/final.h5", src + "/old.h5");
  {
    H5Edit e(src + "/old.h5");
    for (const auto& f : e.fields()) e.make_contiguous("/fields/" + f);
    EXPECT_EQ(e.data_offset("/fields/position") != HADDR_UNDEF, true);
  }
  const std::string a = out_dir("bad_ckpt_run_unchecked"), b = out_dir("bad_ckpt_run_checked");
  auto r = run_limited("run --restart " + src + "/old.h5 --out " + a + " --steps 2");
  ASSERT_EQ(r.code, 0) << r.output;
  ASSERT_EQ(run_limited("run --restart " + src + "/final.h5 --out " + b + " --steps 2").code, 0);
  expect_same_checkpoint(a + "/final.h5", b + "/final.h5");
}

// Under mpirun every rank refuses the damaged file alike (exit 2, no hang).
TEST(BadCheckpoint, MpiRanksRefuseTogether) {
  const std::string src = out_dir("bad_ckpt_src_mpi");
  ASSERT_EQ(run_limited("run " + source("tests/scenes/grain_bounce.yaml") + " --out " + src +
                        " --steps 3")
                .code,
            0);
  H5Edit(src + "/final.h5").set_int("/fields/material", 7, 1000000);
  const std::string out = out_dir("bad_ckpt_run_mpi");
  auto r = run_command("timeout " + std::to_string(kTimeLimitSeconds) +
                       " " MONOSPH_MPIEXEC
                       " --allow-run-as-root --oversubscribe --bind-to none -x OMP_NUM_THREADS=1"
                       " -np 2 " MONOSPH_BIN " run --restart " +
                       src + "/final.h5 --out " + out + " --steps 2 --quiet 2>&1");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("material 1000000"), std::string::npos) << r.output;
}
