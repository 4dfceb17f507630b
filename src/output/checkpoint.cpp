#include "output/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <utility>
#include <vector>

#include "output/atomic_file.hpp"
#include "output/checkpoint_check.hpp"

namespace monosph {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "monosph-checkpoint";
constexpr int kVersion = 1;

// Internal failure; turned into an InputError naming the file at the API boundary.
struct Fail {
  std::string what;
};

// The system error HDF5 recorded for the call that just failed ("errno = 28, error message =
// ..." in its error stack), e.g. "No space left on device"; "" if none.
std::string hdf5_system_error() {
  int code = 0;
  auto find = [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
    const char* at = e->desc ? std::strstr(e->desc, "errno = ") : nullptr;
    if (!at) return 0;
    *static_cast<int*>(data) = std::atoi(at + 8);
    return 1;  // stop
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, find, &code);
  return code > 0 ? std::strerror(code) : "";
}

template <class T>
T ck(T v, const std::string& what) {
  if (v >= 0) return v;
  const std::string why = hdf5_system_error();
  throw Fail{why.empty() ? what : what + ": " + why};
}

// Owns an HDF5 identifier.
class Hid {
 public:
  Hid(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Hid(Hid&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  ~Hid() {
    if (id_ >= 0) close_(id_);
  }
  operator hid_t() const { return id_; }
  // Closes now, reporting failure (file close flushes data).
  void close(const std::string& what) {
    hid_t id = std::exchange(id_, -1);
    ck(close_(id), what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void quiet_hdf5() {
  // No clean-up at exit: after a failed write (disk full) HDF5 1.10 keeps a half-closed file
  // that its exit handler then crashes on (SIGSEGV). Every file is closed before it is used.
  // Effective only before the library's first use (the first call of this function).
  static const bool once = [] {
    H5dont_atexit();
    return true;
  }();
  (void)once;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

// ---- writing helpers ----

void put_attr(hid_t loc, const char* name, hid_t ftype, hid_t mtype, const void* v) {
  Hid sp(ck(H5Screate(H5S_SCALAR), "dataspace"), H5Sclose);
  Hid a(ck(H5Acreate2(loc, name, ftype, sp, H5P_DEFAULT, H5P_DEFAULT),
           std::string("cannot create attribute ") + name),
        H5Aclose);
  ck(H5Awrite(a, mtype, v), std::string("cannot write attribute ") + name);
}
void put_double(hid_t loc, const char* name, double v) {
  put_attr(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v);
}
void put_int(hid_t loc, const char* name, std::int64_t v) {
  put_attr(loc, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &v);
}

// Fixed-length, null-padded string type of n bytes (at least 1).
Hid str_type(std::size_t n) {
  Hid t(ck(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
  ck(H5Tset_size(t, std::max<std::size_t>(n, 1)), "string type");
  ck(H5Tset_strpad(t, H5T_STR_NULLPAD), "string type");
  return t;
}

// Dataset layout: chunks of at most kChunkValues values, each with HDF5's Fletcher32 checksum
// (reading damaged data then fails); an empty dataset stays contiguous.
constexpr hsize_t kChunkValues = 1 << 16;
Hid checked_layout(int rank, const hsize_t* dims) {
  Hid pl(ck(H5Pcreate(H5P_DATASET_CREATE), "property list"), H5Pclose);
  const hsize_t per_row = rank > 1 ? dims[1] : 1;
  if (dims[0] == 0 || per_row == 0) return pl;
  const hsize_t chunk[2] = {std::clamp<hsize_t>(kChunkValues / per_row, 1, dims[0]), per_row};
  ck(H5Pset_chunk(pl, rank, chunk), "chunk layout");
  ck(H5Pset_fletcher32(pl), "checksum filter");
  return pl;
}

Hid create_dataset(hid_t loc, const char* name, hid_t type, int rank, const hsize_t* dims) {
  Hid sp(ck(H5Screate_simple(rank, dims, nullptr), "dataspace"), H5Sclose);
  Hid pl = checked_layout(rank, dims);
  return Hid(ck(H5Dcreate2(loc, name, type, sp, H5P_DEFAULT, pl, H5P_DEFAULT),
                std::string("cannot create dataset ") + name),
             H5Dclose);
}

void put_string_attr(hid_t loc, const char* name, const std::string& s) {
  Hid t = str_type(s.size());
  std::string buf = s.empty() ? std::string(1, '\0') : s;
  put_attr(loc, name, t, t, buf.data());
}

// Array of strings as a 1-D fixed-length string dataset.
void put_strings(hid_t loc, const char* name, const std::vector<std::string>& v) {
  std::size_t len = 1;
  for (const auto& s : v) len = std::max(len, s.size());
  std::vector<char> buf(v.size() * len, '\0');
  for (std::size_t i = 0; i < v.size(); ++i) std::copy(v[i].begin(), v[i].end(), &buf[i * len]);
  Hid t = str_type(len);
  hsize_t dims[1] = {v.size()};
  Hid d = create_dataset(loc, name, t, 1, dims);
  if (!v.empty()) ck(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()), "write strings");
  d.close(std::string("cannot write ") + name);
}

// Writes the first `rows` rows of f as rows [row0, row0 + rows) of dataset d.
void put_rows(hid_t d, const Field& f, std::size_t row0, std::size_t rows) {
  if (rows == 0) return;
  const bool real = f.type == FieldType::Real;
  Hid sp(ck(H5Dget_space(d), "dataspace"), H5Sclose);
  const hsize_t start[2] = {row0, 0}, count[2] = {rows, static_cast<hsize_t>(f.ncomp)};
  ck(H5Sselect_hyperslab(sp, H5S_SELECT_SET, start, nullptr, count, nullptr), "hyperslab");
  Hid mem(ck(H5Screate_simple(2, count, nullptr), "dataspace"), H5Sclose);
  const void* data = real ? static_cast<const void*>(f.real.data()) : f.ints.data();
  ck(H5Dwrite(d, real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, mem, sp, H5P_DEFAULT, data),
     "cannot write field '" + f.name + "'");
}

// Dataset of n rows for f, holding f's first `rows` rows at the top.
void put_field(hid_t group, const Field& f, std::size_t n, std::size_t rows) {
  const bool real = f.type == FieldType::Real;
  hsize_t dims[2] = {n, static_cast<hsize_t>(f.ncomp)};
  Hid d = create_dataset(group, f.name.c_str(), real ? H5T_IEEE_F64LE : H5T_STD_I64LE, 2, dims);
  put_rows(d, f, 0, rows);
  put_int(d, "ncomp", f.ncomp);
  put_int(d, "output", f.output ? 1 : 0);
  d.close("cannot write field '" + f.name + "'");  // writes its chunks: may fail (disk full)
}

// ---- reading helpers ----

// A dataset whose data cannot be read back: its checksum failed (or the file is cut short).
std::string unreadable(const std::string& dataset) {
  return "dataset " + dataset + ": data unreadable (checksum mismatch: the file is damaged)";
}

void get_attr(hid_t loc, const char* name, hid_t mtype, void* v) {
  if (H5Aexists(loc, name) <= 0) throw Fail{std::string("missing attribute ") + name};
  Hid a(ck(H5Aopen(loc, name, H5P_DEFAULT), std::string("cannot open attribute ") + name),
        H5Aclose);
  ck(H5Aread(a, mtype, v), std::string("cannot read attribute ") + name);
}
double get_double(hid_t loc, const char* name) {
  double v = 0;
  get_attr(loc, name, H5T_NATIVE_DOUBLE, &v);
  return v;
}
std::int64_t get_int(hid_t loc, const char* name) {
  std::int64_t v = 0;
  get_attr(loc, name, H5T_NATIVE_INT64, &v);
  return v;
}

// Strips the null padding of a fixed-length string.
std::string unpad(const char* p, std::size_t n) {
  return std::string(p, std::find(p, p + n, '\0'));
}

std::string get_string_attr(hid_t loc, const char* name) {
  if (H5Aexists(loc, name) <= 0) throw Fail{std::string("missing attribute ") + name};
  Hid a(ck(H5Aopen(loc, name, H5P_DEFAULT), std::string("cannot open attribute ") + name),
        H5Aclose);
  Hid t(ck(H5Aget_type(a), "attribute type"), H5Tclose);
  if (H5Tget_class(t) != H5T_STRING || H5Tis_variable_str(t) != 0)
    throw Fail{std::string("attribute ") + name + " is not a string"};
  std::vector<char> buf(H5Tget_size(t));
  ck(H5Aread(a, t, buf.data()), std::string("cannot read attribute ") + name);
  return unpad(buf.data(), buf.size());
}

std::vector<std::string> get_strings(hid_t loc, const char* name) {
  Hid d(ck(H5Dopen2(loc, name, H5P_DEFAULT), std::string("missing dataset ") + name), H5Dclose);
  Hid t(ck(H5Dget_type(d), "dataset type"), H5Tclose);
  Hid sp(ck(H5Dget_space(d), "dataspace"), H5Sclose);
  if (H5Tget_class(t) != H5T_STRING || H5Tis_variable_str(t) != 0 ||
      H5Sget_simple_extent_ndims(sp) != 1)
    throw Fail{std::string("dataset ") + name + " is not a string array"};
  hsize_t n = 0;
  H5Sget_simple_extent_dims(sp, &n, nullptr);
  const std::size_t len = H5Tget_size(t);
  std::vector<char> buf(n * len);
  if (n > 0)
    ck(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data()),
       unreadable(std::string("/meta/") + name));
  std::vector<std::string> v;
  for (hsize_t i = 0; i < n; ++i) v.push_back(unpad(&buf[i * len], len));
  return v;
}

std::vector<double> get_doubles(hid_t loc, const char* name) {
  Hid d(ck(H5Dopen2(loc, name, H5P_DEFAULT), std::string("missing dataset ") + name), H5Dclose);
  Hid sp(ck(H5Dget_space(d), "dataspace"), H5Sclose);
  hssize_t n = ck(H5Sget_simple_extent_npoints(sp), "dataspace");
  std::vector<double> v(n);
  if (n > 0)
    ck(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
       unreadable(std::string("/meta/") + name));
  return v;
}

// Reads /fields/<name>; n is the particle count (set by the first field, then checked).
// Reads rows [n part / parts, n (part + 1) / parts) of the field (all rows with parts = 1);
// n is the file's particle count.
Field get_field(hid_t group, const std::string& name, std::size_t& n, bool first, int part,
                int parts) {
  Hid d(ck(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "cannot open field '" + name + "'"),
        H5Dclose);
  Hid t(ck(H5Dget_type(d), "dataset type"), H5Tclose);
  Hid sp(ck(H5Dget_space(d), "dataspace"), H5Sclose);
  Field f;
  f.name = name;
  const H5T_class_t cls = H5Tget_class(t);
  if (cls != H5T_FLOAT && cls != H5T_INTEGER) throw Fail{"field '" + name + "' has a bad type"};
  f.type = cls == H5T_FLOAT ? FieldType::Real : FieldType::Int;
  f.ncomp = static_cast<int>(get_int(d, "ncomp"));
  f.output = get_int(d, "output") != 0;
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(sp) != 2 || H5Sget_simple_extent_dims(sp, dims, nullptr) < 0 ||
      dims[1] != static_cast<hsize_t>(f.ncomp) || f.ncomp < 1)
    throw Fail{"field '" + name + "' has a bad shape"};
  if (first) n = dims[0];
  if (dims[0] != n) throw Fail{"field '" + name + "' has a different particle count"};
  const hsize_t r0 = n * part / parts, r1 = n * (part + 1) / parts;
  const std::size_t count = (r1 - r0) * f.ncomp;
  void* data;
  if (f.type == FieldType::Real) {
    f.real.resize(count);
    data = f.real.data();
  } else {
    f.ints.resize(count);
    data = f.ints.data();
  }
  if (count > 0) {
    const hsize_t start[2] = {r0, 0}, rows[2] = {r1 - r0, static_cast<hsize_t>(f.ncomp)};
    ck(H5Sselect_hyperslab(sp, H5S_SELECT_SET, start, nullptr, rows, nullptr), "hyperslab");
    Hid mem(ck(H5Screate_simple(2, rows, nullptr), "dataspace"), H5Sclose);
    ck(H5Dread(d, f.type == FieldType::Real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64, mem, sp,
               H5P_DEFAULT, data),
       unreadable("/fields/" + name));
  }
  return f;
}

void put_meta(hid_t file, const CheckpointMeta& meta, std::int64_t next_id, int dim) {
  Hid m(ck(H5Gcreate2(file, "meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "group meta"),
        H5Gclose);
  put_double(m, "time", meta.time);
  put_int(m, "step", meta.step);
  put_double(m, "dt", meta.dt);
  put_int(m, "next_id", next_id);
  put_int(m, "dimension", dim);
  put_strings(m, "scene_yaml", {meta.scene_yaml});
  std::vector<std::string> keys;
  std::vector<double> vals;
  for (const auto& [k, v] : meta.scalars) {
    keys.push_back(k);
    vals.push_back(v);
  }
  put_strings(m, "scalar_names", keys);
  hsize_t ns[1] = {vals.size()};
  Hid d = create_dataset(m, "scalar_values", H5T_IEEE_F64LE, 1, ns);
  if (!vals.empty())
    ck(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, vals.data()), "scalars");
  d.close("cannot write scalar_values");
  m.close("cannot write group meta");
}

// Flushes and closes a file whose objects are all closed; throws Fail on a failed write.
void finish_file(Hid& file) {
  ck(H5Fflush(file, H5F_SCOPE_LOCAL), "write failed");
  file.close("write failed");
}

// File format 1.10 (readable by HDF5 1.10 and later): checksummed object headers and compact
// chunk indexes (format 1.8 B-trees made a small checkpoint 30 % larger).
Hid file_access() {
  Hid fapl(ck(H5Pcreate(H5P_FILE_ACCESS), "property list"), H5Pclose);
  ck(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_V110), "file format");
  // A close with objects still open fails instead of being put off to the last object's close.
  ck(H5Pset_fclose_degree(fapl, H5F_CLOSE_SEMI), "close degree");
  return fapl;
}

// A new file with n particles; the first `rows` of them from `fields` (all when rows = n).
void write_file(const fs::path& tmp, const std::vector<Field>& fields, std::size_t n,
                std::size_t rows, const CheckpointMeta& meta, std::int64_t next_id, int dim) {
  Hid file(ck(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, file_access()),
              "cannot create the file"),
           H5Fclose);
  put_string_attr(file, "format", kFormat);
  put_int(file, "version", kVersion);
  put_meta(file, meta, next_id, dim);
  {
    // Track creation order so fields come back in the order they were registered.
    Hid gcpl(ck(H5Pcreate(H5P_GROUP_CREATE), "property list"), H5Pclose);
    ck(H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), "plist");
    Hid g(ck(H5Gcreate2(file, "fields", H5P_DEFAULT, gcpl, H5P_DEFAULT), "group fields"), H5Gclose);
    for (const auto& f : fields) {
      if (f.name.empty() || f.name.find('/') != std::string::npos || f.name == ".")
        throw Fail{"field name '" + f.name + "' cannot be stored"};
      put_field(g, f, n, rows);
    }
    g.close("cannot write group fields");
  }
  finish_file(file);
}

// Rows [row0, row0 + rows) of every field of an existing file.
void write_rows(const fs::path& tmp, const std::vector<Field>& fields, std::size_t row0,
                std::size_t rows) {
  Hid file(ck(H5Fopen(tmp.c_str(), H5F_ACC_RDWR, file_access()), "cannot open the file"), H5Fclose);
  {
    Hid g(ck(H5Gopen2(file, "fields", H5P_DEFAULT), "group fields"), H5Gclose);
    for (const auto& f : fields) {
      Hid d(ck(H5Dopen2(g, f.name.c_str(), H5P_DEFAULT), "cannot open field '" + f.name + "'"),
            H5Dclose);
      put_rows(d, f, row0, rows);
      d.close("cannot write field '" + f.name + "'");
    }
    g.close("cannot write group fields");
  }
  finish_file(file);
}

}  // namespace

template <int D>
void write_checkpoint(const fs::path& file, const Particles<D>& p, const CheckpointMeta& meta) {
  quiet_hdf5();
  const fs::path tmp = temporary_name(file);
  try {
    write_file(tmp, p.fields(), p.size(), p.size(), meta, std::max(meta.next_id, p.next_id()), D);
  } catch (const Fail& e) {
    std::error_code ec;
    fs::remove(tmp, ec);
    cannot_write_file(file, e.what);
  }
  commit_file(tmp, file);  // fsync, rename
}

template <int D>
void write_checkpoint(const fs::path& file, const Particles<D>& p, std::size_t owned,
                      const CheckpointMeta& meta, const Comm& comm) {
  if (!comm.parallel()) return write_checkpoint(file, p, meta);
  quiet_hdf5();
  // Rank r's rows follow those of ranks < r; the ranks write in turn into one file.
  std::vector<double> counts(comm.size(), 0.0);
  counts[comm.rank()] = static_cast<double>(owned);
  comm.sum(counts);
  std::size_t row0 = 0, total = 0;
  for (int r = 0; r < comm.size(); ++r) {
    if (r < comm.rank()) row0 += static_cast<std::size_t>(counts[r]);
    total += static_cast<std::size_t>(counts[r]);
  }
  const std::int64_t next_id =
      static_cast<std::int64_t>(comm.max(static_cast<double>(std::max(meta.next_id, p.next_id()))));
  const fs::path tmp = temporary_name(file);
  std::string err;
  for (int r = 0; r < comm.size() && err.empty(); ++r) {
    if (r == comm.rank()) {
      try {
        if (r == 0)
          write_file(tmp, p.fields(), total, owned, meta, next_id, D);
        else
          write_rows(tmp, p.fields(), row0, owned);
      } catch (const Fail& e) {
        err = e.what;
      }
    }
    err = comm.first_message(err);  // also the turn: rank r has closed the file
  }
  if (!err.empty()) {
    std::error_code ec;
    if (comm.root()) fs::remove(tmp, ec);
    cannot_write_file(file, err);
  }
  if (comm.root()) {
    try {
      commit_file(tmp, file);
    } catch (const OutputError& e) {
      err = e.what();
    }
  }
  err = comm.first_message(err);
  if (!err.empty()) throw OutputError(err);
}

namespace {

std::string where(const fs::path& file) {
  return "checkpoint " + file.string() + ": ";
}

// Opens a monosph checkpoint read-only; throws InputError or Fail otherwise.
Hid open_checkpoint(const fs::path& file) {
  quiet_hdf5();
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(where(file) + "no such file");
  if (!fs::is_regular_file(file, ec)) throw InputError(where(file) + "not a regular file");
  if (H5Fis_hdf5(file.c_str()) <= 0) throw InputError(where(file) + "not a monosph checkpoint");
  Hid f(ck(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "cannot open the file"), H5Fclose);
  std::string fmt;
  try {
    fmt = get_string_attr(f, "format");
  } catch (const Fail&) {
  }
  if (fmt != kFormat) throw Fail{"not a monosph checkpoint"};
  if (get_int(f, "version") != kVersion) throw Fail{"unsupported checkpoint version"};
  return f;
}

int dimension_of(hid_t f) {
  Hid m(ck(H5Gopen2(f, "meta", H5P_DEFAULT), "missing group meta"), H5Gclose);
  const std::int64_t dim = get_int(m, "dimension");
  if (dim != 2 && dim != 3) throw Fail{"bad dimension " + std::to_string(dim)};
  return static_cast<int>(dim);
}

}  // namespace

int checkpoint_dimension(const fs::path& file) {
  try {
    Hid f = open_checkpoint(file);
    return dimension_of(f);
  } catch (const Fail& e) {
    throw InputError(where(file) + e.what);
  }
}

template <int D>
CheckpointMeta read_checkpoint(const fs::path& file, Particles<D>& p, int part, int parts) {
  CheckpointMeta meta;
  std::vector<Field> fields;
  std::size_t n = 0;
  try {
    Hid f = open_checkpoint(file);
    const int dim = dimension_of(f);
    if (dim != D)
      throw Fail{"written by a " + std::to_string(dim) + "D run, cannot restart a " +
                 std::to_string(D) + "D run"};
    Hid m(ck(H5Gopen2(f, "meta", H5P_DEFAULT), "missing group meta"), H5Gclose);
    meta.time = get_double(m, "time");
    meta.step = static_cast<long>(get_int(m, "step"));
    meta.dt = get_double(m, "dt");
    meta.next_id = get_int(m, "next_id");
    auto yaml = get_strings(m, "scene_yaml");
    if (yaml.size() != 1) throw Fail{"bad scene_yaml"};
    meta.scene_yaml = yaml[0];
    auto keys = get_strings(m, "scalar_names");
    auto vals = get_doubles(m, "scalar_values");
    if (keys.size() != vals.size()) throw Fail{"bad scalars"};
    for (std::size_t i = 0; i < keys.size(); ++i) meta.scalars[keys[i]] = vals[i];

    Hid g(ck(H5Gopen2(f, "fields", H5P_DEFAULT), "missing group fields"), H5Gclose);
    H5G_info_t info;
    ck(H5Gget_info(g, &info), "group fields");
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      ssize_t len = ck(
          H5Lget_name_by_idx(g, ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT),
          "field names");
      std::string name(len + 1, '\0');
      ck(H5Lget_name_by_idx(g, ".", H5_INDEX_CRT_ORDER, H5_ITER_INC, i, name.data(), len + 1,
                            H5P_DEFAULT),
         "field names");
      name.resize(len);
      fields.push_back(get_field(g, name, n, i == 0, part, parts));
    }
    auto pos = std::find_if(fields.begin(), fields.end(),
                            [](const Field& x) { return x.name == "position"; });
    if (pos == fields.end() || pos->ncomp != D || pos->type != FieldType::Real)
      throw Fail{"missing or bad position field"};
    // Check shapes against fields p already has before changing anything.
    for (const auto& x : fields) {
      int k = p.find(x.name);
      if (k >= 0 && (p.field(k).ncomp != x.ncomp || p.field(k).type != x.type))
        throw Fail{"field '" + x.name + "' does not match this build"};
    }
    const Particles<D> always;  // the fields every particle has
    for (const auto& x : always.fields())
      if (std::none_of(fields.begin(), fields.end(),
                       [&](const Field& y) { return y.name == x.name; }))
        throw Fail{"missing dataset /fields/" + x.name};
    if (auto e = check_checkpoint_data(fields, meta); !e.empty()) throw Fail{e};
  } catch (const Fail& e) {
    throw InputError(where(file) + e.what);
  }

  p.resize(n * (part + 1) / parts - n * part / parts);
  for (auto& x : fields) {
    Field& dst = p.field(p.add_field(x.name, x.ncomp, x.type, x.output));
    dst.output = x.output;
    dst.real = std::move(x.real);
    dst.ints = std::move(x.ints);
  }
  p.set_next_id(meta.next_id);
  return meta;
}

template void write_checkpoint<2>(const fs::path&, const Particles<2>&, const CheckpointMeta&);
template void write_checkpoint<2>(const fs::path&, const Particles<2>&, std::size_t,
                                  const CheckpointMeta&, const Comm&);
template void write_checkpoint<3>(const fs::path&, const Particles<3>&, std::size_t,
                                  const CheckpointMeta&, const Comm&);
template void write_checkpoint<3>(const fs::path&, const Particles<3>&, const CheckpointMeta&);
template CheckpointMeta read_checkpoint<2>(const fs::path&, Particles<2>&, int, int);
template CheckpointMeta read_checkpoint<3>(const fs::path&, Particles<3>&, int, int);

}  // namespace monosph
