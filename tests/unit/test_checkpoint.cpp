// Checkpoints: bit-exact round trip of every field, metadata, and clean errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "output/checkpoint.hpp"

namespace monosph {
namespace {
namespace fs = std::filesystem;

struct TmpDir {
  fs::path path;
  explicit TmpDir(const std::string& tag) {
    path = fs::temp_directory_path() / ("monosph_ckpt_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TmpDir() { fs::remove_all(path); }
};

// Random particles with extra fields of every shape and type, including awkward values.
template <int D>
void make_random(Particles<D>& p, std::size_t n, unsigned seed) {
  p.add_field("stress", D * D, FieldType::Real, true);
  p.add_field("rot3", 9, FieldType::Real, false);
  p.add_field("neigh", 1, FieldType::Int, true);
  p.add_field("pair", 2, FieldType::Int, false);
  p.append(n);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (auto& f : p.fields()) {
    if (f.type == FieldType::Real) {
      for (auto& x : f.real) x = u(rng) * std::exp(u(rng) / 100.0);
    } else {
      for (auto& x : f.ints) x = static_cast<std::int64_t>(rng());
    }
  }
  for (std::size_t i = 0; i < n; ++i) p.id()[i] = static_cast<std::int64_t>(n - 1 - i);  // distinct
  if (n > 2) {
    p.rho()[0] = std::numeric_limits<double>::denorm_min();
    p.rho()[1] = -0.0;
    p.rho()[2] = std::numeric_limits<double>::max();
  }
}

template <int D>
void expect_identical(const Particles<D>& a, const Particles<D>& b, bool same_order = true) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.fields().size(), b.fields().size());
  for (std::size_t k = 0; k < a.fields().size(); ++k) {
    const Field& fa = a.fields()[k];
    if (same_order) {
      EXPECT_EQ(fa.name, b.fields()[k].name);
    }
    ASSERT_TRUE(b.has(fa.name)) << fa.name;
    const Field& fb = b.field(fa.name);
    EXPECT_EQ(fa.ncomp, fb.ncomp) << fa.name;
    EXPECT_EQ(fa.type, fb.type) << fa.name;
    EXPECT_EQ(fa.output, fb.output) << fa.name;
    ASSERT_EQ(fa.real.size(), fb.real.size()) << fa.name;
    ASSERT_EQ(fa.ints.size(), fb.ints.size()) << fa.name;
    if (!fa.real.empty()) {
      EXPECT_EQ(std::memcmp(fa.real.data(), fb.real.data(), fa.real.size() * sizeof(double)), 0)
          << fa.name;
    }
    EXPECT_EQ(fa.ints, fb.ints) << fa.name;
  }
  EXPECT_EQ(a.next_id(), b.next_id());
}

CheckpointMeta sample_meta() {
  CheckpointMeta m;
  m.time = 0.1 + 0.2;
  m.step = 123456789012L;
  m.dt = 1.0 / 3.0;
  m.scene_yaml = "dimension: 2\nname: \"dam break\"\n# comment with ünïcode\n";
  m.next_id = 5;
  m.scalars = {{"rigid.0.omega", -2.5}, {"counter", 42.0}, {"tiny", 1e-300}};
  return m;
}

void expect_meta_equal(const CheckpointMeta& a, const CheckpointMeta& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.dt, b.dt);
  EXPECT_EQ(a.scene_yaml, b.scene_yaml);
  EXPECT_EQ(a.next_id, b.next_id);
  EXPECT_EQ(a.scalars, b.scalars);
}

template <int D>
void round_trip(std::size_t n) {
  TmpDir tmp("rt" + std::to_string(D) + "_" + std::to_string(n));
  Particles<D> p;
  make_random(p, n, 17 + D);
  CheckpointMeta meta = sample_meta();
  meta.next_id = static_cast<std::int64_t>(n) + 100;  // larger than p.next_id()
  const fs::path file = tmp.path / "state.h5";
  write_checkpoint(file, p, meta);
  EXPECT_TRUE(fs::exists(file));
  EXPECT_FALSE(fs::exists(tmp.path / "state.h5.tmp"));

  // A fresh container: extra fields must be registered by read_checkpoint.
  Particles<D> q;
  CheckpointMeta back = read_checkpoint(file, q);
  expect_meta_equal(meta, back);
  p.set_next_id(meta.next_id);
  expect_identical(p, q);

  // Reading into a container that already has data and some of the fields.
  Particles<D> r;
  r.add_field("neigh", 1, FieldType::Int, false);
  r.append(3);
  read_checkpoint(file, r);
  expect_identical(p, r, false);
}

TEST(Checkpoint, RoundTrip2D) {
  round_trip<2>(50);
}
TEST(Checkpoint, RoundTrip3D) {
  round_trip<3>(50);
}
TEST(Checkpoint, RoundTripEmpty) {
  round_trip<3>(0);
}

TEST(Checkpoint, NextIdFromParticles) {
  TmpDir tmp("nextid");
  Particles<2> p;
  p.append(10);
  CheckpointMeta meta;  // next_id = 0: the particles' counter wins
  write_checkpoint(tmp.path / "c.h5", p, meta);
  Particles<2> q;
  EXPECT_EQ(read_checkpoint(tmp.path / "c.h5", q).next_id, 10);
  EXPECT_EQ(q.next_id(), 10);
  EXPECT_EQ(q.size(), 10u);
}

TEST(Checkpoint, OverwriteExisting) {
  TmpDir tmp("overwrite");
  Particles<2> p;
  make_random(p, 5, 1);
  const fs::path file = tmp.path / "c.h5";
  write_checkpoint(file, p, sample_meta());
  Particles<2> p2;
  make_random(p2, 9, 2);
  write_checkpoint(file, p2, sample_meta());
  Particles<2> q;
  read_checkpoint(file, q);
  p2.set_next_id(std::max<std::int64_t>(p2.next_id(), 5));
  expect_identical(p2, q);
}

void expect_input_error(const fs::path& file, const std::string& part) {
  Particles<2> p;
  p.append(4);
  const auto before = p.fields()[0].real;
  try {
    read_checkpoint(file, p);
    FAIL() << "expected InputError for " << file;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  EXPECT_EQ(p.size(), 4u);  // left unchanged
  EXPECT_EQ(p.fields()[0].real, before);
}

TEST(Checkpoint, MissingFileThrows) {
  TmpDir tmp("missing");
  expect_input_error(tmp.path / "nope.h5", "no such file");
}

TEST(Checkpoint, GarbageFileThrows) {
  TmpDir tmp("garbage");
  const fs::path file = tmp.path / "garbage.h5";
  std::ofstream(file) << "this is not an HDF5 file at all\n";
  expect_input_error(file, "not a monosph checkpoint");
  expect_input_error(tmp.path, "not a regular file");
}

TEST(Checkpoint, TruncatedFileThrows) {
  TmpDir tmp("trunc");
  Particles<2> p;
  make_random(p, 200, 3);
  const fs::path file = tmp.path / "c.h5";
  write_checkpoint(file, p, sample_meta());
  fs::resize_file(file, fs::file_size(file) / 2);
  Particles<2> q;
  EXPECT_THROW(read_checkpoint(file, q), InputError);
}

TEST(Checkpoint, WrongDimensionThrows) {
  TmpDir tmp("dim");
  Particles<3> p;
  make_random(p, 4, 5);
  const fs::path file = tmp.path / "c3.h5";
  write_checkpoint(file, p, sample_meta());
  expect_input_error(file, "3D");
  EXPECT_EQ(checkpoint_dimension(file), 3);
  Particles<2> p2;
  p2.append(1);
  write_checkpoint(tmp.path / "c2.h5", p2, CheckpointMeta{});
  EXPECT_EQ(checkpoint_dimension(tmp.path / "c2.h5"), 2);
  EXPECT_THROW(checkpoint_dimension(tmp.path / "none.h5"), InputError);
  std::ofstream(tmp.path / "bad.h5") << "garbage";
  EXPECT_THROW(checkpoint_dimension(tmp.path / "bad.h5"), InputError);
}

TEST(Checkpoint, UnwritableThrows) {
  TmpDir tmp("unwritable");
  const fs::path file = tmp.path / "regular_file";
  std::ofstream(file) << "x";
  Particles<2> p;
  p.append(2);
  EXPECT_THROW(write_checkpoint(file / "c.h5", p, CheckpointMeta{}), OutputError);
  EXPECT_THROW(write_checkpoint(tmp.path / "no" / "dir" / "c.h5", p, CheckpointMeta{}),
               OutputError);
}

}  // namespace
}  // namespace monosph
