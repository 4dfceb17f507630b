#include "parallel/decomposition.hpp"

#include <zoltan.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "parallel/comm_mpi.hpp"

namespace monosph {

struct MpiRequests {
  std::vector<MPI_Request> v;
};

namespace {
// ---- packing: all fields of particles idx, field by field --------------------------------------
template <int D>
void pack_particles(const Particles<D>& p, std::span<const int> idx, std::vector<char>& buf) {
  const std::int64_t n = static_cast<std::int64_t>(idx.size());
  std::size_t bytes = sizeof(n);
  for (const Field& f : p.fields()) bytes += idx.size() * f.ncomp * 8;
  const std::size_t off0 = buf.size();
  buf.resize(off0 + bytes);
  char* out = buf.data() + off0;
  std::memcpy(out, &n, sizeof(n));
  out += sizeof(n);
  for (const Field& f : p.fields()) {
    const char* src = f.type == FieldType::Real ? reinterpret_cast<const char*>(f.real.data())
                                                : reinterpret_cast<const char*>(f.ints.data());
    const std::size_t row = static_cast<std::size_t>(f.ncomp) * 8;
    for (int i : idx) {
      std::memcpy(out, src + static_cast<std::size_t>(i) * row, row);
      out += row;
    }
  }
}

template <int D>
std::size_t unpack_particles(Particles<D>& p, const std::vector<char>& buf) {
  std::size_t read = 0, total = 0;
  while (read < buf.size()) {
    std::int64_t n;
    std::memcpy(&n, buf.data() + read, sizeof(n));
    read += sizeof(n);
    const std::size_t first = p.size();
    p.resize(first + n);
    for (Field& f : p.fields()) {
      char* dst = f.type == FieldType::Real ? reinterpret_cast<char*>(f.real.data())
                                            : reinterpret_cast<char*>(f.ints.data());
      const std::size_t row = static_cast<std::size_t>(f.ncomp) * 8;
      std::memcpy(dst + first * row, buf.data() + read, n * row);
      read += n * row;
    }
    total += n;
  }
  return total;
}

// ---- Zoltan callbacks ------------------------------------------------------------------------
template <int D>
struct ZData {
  Particles<D>* p;
  const std::vector<float>* work;
};
template <int D>
int num_obj(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<ZData<D>*>(data)->p->size());
}
template <int D>
void obj_list(void* data, int, int, ZOLTAN_ID_PTR gid, ZOLTAN_ID_PTR lid, int, float* w,
              int* ierr) {
  auto& p = *static_cast<ZData<D>*>(data)->p;
  const auto& work = *static_cast<ZData<D>*>(data)->work;
  auto id = p.id();
  for (std::size_t i = 0; i < p.size(); ++i) {
    gid[i] = static_cast<ZOLTAN_ID_TYPE>(id[i]), lid[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    w[i] = i < work.size() ? work[i] : 1.0f;
  }
  *ierr = ZOLTAN_OK;
}
template <int D>
int num_geom(void*, int* ierr) {
  *ierr = ZOLTAN_OK;
  return D;
}
template <int D>
void geom_multi(void* data, int, int, int num, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lid, int, double* g,
                int* ierr) {
  auto x = static_cast<ZData<D>*>(data)->p->x();
  for (int q = 0; q < num; ++q)
    for (int a = 0; a < D; ++a) g[q * D + a] = x[lid[q]][a];
  *ierr = ZOLTAN_OK;
}
}  // namespace

template <int D>
Decomposition<D>::Decomposition(const Comm& comm, const Domain<D>& dom, double halo,
                                double imbalance)
    : comm_(comm),
      dom_(dom),
      halo_(halo),
      imbalance_(imbalance),
      req_(std::make_unique<MpiRequests>()) {
  static bool initialised = false;
  if (!initialised) {
    float ver;
    if (Zoltan_Initialize(0, nullptr, &ver) != ZOLTAN_OK)
      throw std::runtime_error("Zoltan_Initialize failed");
    initialised = true;
  }
  zz_ = Zoltan_Create(mpi_comm(comm_));
  Zoltan_Set_Param(zz_, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz_, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz_, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz_, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz_, "OBJ_WEIGHT_DIM", "1");  // balance work, not particle counts
  Zoltan_Set_Param(zz_, "RETURN_LISTS", "EXPORT");
  Zoltan_Set_Param(zz_, "KEEP_CUTS", "1");  // for Point_Assign and Box_Assign
  Zoltan_Set_Param(zz_, "RCB_REUSE", "1");  // start from the previous cuts: little migration
  Zoltan_Set_Param(zz_, "IMBALANCE_TOL", "1.01");
  Zoltan_Set_Param(zz_, "AVERAGE_CUTS", "1");
}

template <int D>
Decomposition<D>::~Decomposition() {
  if (zz_) Zoltan_Destroy(&zz_);
}

template <int D>
void Decomposition<D>::partition(Particles<D>& p, const std::vector<float>& work) {
  ZData<D> data{&p, &work};
  Zoltan_Set_Num_Obj_Fn(zz_, num_obj<D>, &data);
  Zoltan_Set_Obj_List_Fn(zz_, obj_list<D>, &data);
  Zoltan_Set_Num_Geom_Fn(zz_, num_geom<D>, &data);
  Zoltan_Set_Geom_Multi_Fn(zz_, geom_multi<D>, &data);
  int changes, ngid, nlid, nimp, nexp;
  ZOLTAN_ID_PTR igid, ilid, egid, elid;
  int *iproc, *ipart, *eproc, *epart;
  if (Zoltan_LB_Partition(zz_, &changes, &ngid, &nlid, &nimp, &igid, &ilid, &iproc, &ipart, &nexp,
                          &egid, &elid, &eproc, &epart) != ZOLTAN_OK)
    throw std::runtime_error("Zoltan RCB partition failed");
  have_cuts_ = true;
  ++stats_.rebalances;
  Zoltan_LB_Free_Part(&igid, &ilid, &iproc, &ipart);
  Zoltan_LB_Free_Part(&egid, &elid, &eproc, &epart);
}

template <int D>
void Decomposition<D>::migrate(Particles<D>& p, const std::vector<float>& work) {
  const auto tw = std::chrono::steady_clock::now();
  const long n = static_cast<long>(p.size());
  double mine = 0;
  for (std::size_t i = 0; i < p.size(); ++i) mine += i < work.size() ? work[i] : 1.0;
  const double mean = comm_.sum(mine) / comm_.size();  // waits for all ranks
  auto t0 = std::chrono::steady_clock::now();
  stats_.wait_seconds += std::chrono::duration<double>(t0 - tw).count();
  stats_.imbalance = mean > 0 ? comm_.max(mine) / mean : 1.0;
  if (!have_cuts_ || stats_.imbalance > imbalance_) partition(p, work);
  // Every particle goes to the rank whose region holds it (the cuts cover all of space); those
  // still inside this rank's box stay without a query.
  auto x = p.x();
  std::vector<std::vector<int>> out(comm_.size());
  std::vector<char> stay(n, 1);
  int ndim;
  double lo[3], hi[3];
  Zoltan_RCB_Box(zz_, comm_.rank(), &ndim, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]);
  for (long i = 0; i < n; ++i) {
    bool inside = true;
    for (int a = 0; a < D; ++a) inside = inside && x[i][a] > lo[a] && x[i][a] < hi[a];
    if (inside) continue;
    double c[3] = {0, 0, 0};
    for (int a = 0; a < D; ++a) c[a] = x[i][a];
    int proc = comm_.rank();
    Zoltan_LB_Point_Assign(zz_, c, &proc);
    if (proc != comm_.rank()) out[proc].push_back(static_cast<int>(i)), stay[i] = 0;
  }
  std::vector<std::vector<char>> send(comm_.size());
  long moved = 0;
  for (int r = 0; r < comm_.size(); ++r)
    if (!out[r].empty()) pack_particles(p, out[r], send[r]), moved += out[r].size();
  auto recv = comm_.exchange(send);
  std::vector<int> keep;
  for (long i = 0; i < n; ++i)
    if (stay[i]) keep.push_back(static_cast<int>(i));
  if (moved) p.compact(keep);
  for (const auto& b : recv) unpack_particles(p, b);
  stats_.migrated += moved;
  owned_ = p.size();
  ghosts_ = 0;
  stats_.rebuild_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <int D>
void Decomposition<D>::make_ghosts(Particles<D>& p) {
  auto t0 = std::chrono::steady_clock::now();
  const int me = comm_.rank(), np = comm_.size();
  owned_ = p.size();
  int ndim;
  double lo[3], hi[3];
  Zoltan_RCB_Box(zz_, me, &ndim, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]);
  const Vec<D> len = dom_.length();
  auto x = p.x();
  std::vector<std::vector<int>> to(np);
  std::vector<int> procs(np);
  std::vector<char> seen(np, 0);
  for (std::size_t i = 0; i < owned_; ++i) {
    // Images to query: the particle itself, plus its shifts across nearby periodic borders.
    std::array<int, D> smin, smax;
    bool inside = true;
    for (int a = 0; a < D; ++a) {
      smin[a] = smax[a] = 0;
      if (dom_.periodic[a]) {
        if (x[i][a] - halo_ < dom_.lo[a]) smax[a] = 1;
        if (x[i][a] + halo_ >= dom_.hi[a]) smin[a] = -1;
      }
      inside = inside && smin[a] == 0 && smax[a] == 0 && x[i][a] - halo_ > lo[a] &&
               x[i][a] + halo_ < hi[a];
    }
    if (inside) continue;  // its whole halo box lies in this rank's region
    std::vector<int> hits;
    std::array<int, D> s = smin;
    while (true) {
      double b0[3] = {0, 0, 0}, b1[3] = {0, 0, 0};
      for (int a = 0; a < D; ++a) {
        const double c = x[i][a] + s[a] * len[a];
        b0[a] = c - halo_, b1[a] = c + halo_;
      }
      int count = 0;
      Zoltan_LB_Box_Assign(zz_, b0[0], b0[1], b0[2], b1[0], b1[1], b1[2], procs.data(), &count);
      for (int q = 0; q < count; ++q)
        if (procs[q] != me && !seen[procs[q]]) seen[procs[q]] = 1, hits.push_back(procs[q]);
      int a = 0;
      while (a < D && ++s[a] > smax[a]) s[a] = smin[a], ++a;
      if (a == D) break;
    }
    for (int r : hits) to[r].push_back(static_cast<int>(i)), seen[r] = 0;
  }
  std::vector<std::vector<char>> send(np);
  for (int r = 0; r < np; ++r)
    if (!to[r].empty()) pack_particles(p, to[r], send[r]);
  auto recv = comm_.exchange(send);
  peers_.clear(), send_.clear(), recv_first_.clear(), recv_count_.clear();
  for (int r = 0; r < np; ++r) {
    if (to[r].empty() && recv[r].empty()) continue;
    peers_.push_back(r);
    send_.push_back(std::move(to[r]));
    recv_first_.push_back(p.size());
    recv_count_.push_back(unpack_particles(p, recv[r]));
  }
  ghosts_ = p.size() - owned_;
  stats_.peers = static_cast<long>(peers_.size());
  sbuf_.resize(peers_.size());
  rbuf_.resize(peers_.size());
  stats_.rebuild_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <int D>
void Decomposition<D>::exchange(Particles<D>& p, std::span<const int> fields) {
  if (fields.empty()) return;
  ++stats_.exchanges;
  if (peers_.empty()) return;
  auto t0 = std::chrono::steady_clock::now();
  std::size_t row = 0;  // bytes per particle
  for (int k : fields) row += static_cast<std::size_t>(p.field(k).ncomp) * 8;
  auto& req = req_->v;  // kept: no allocation per exchange
  req.resize(2 * peers_.size());
  constexpr int tag = 23;
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    rbuf_[q].resize(recv_count_[q] * row);
    MPI_Irecv(rbuf_[q].data(), static_cast<int>(rbuf_[q].size()), MPI_BYTE, peers_[q], tag,
              mpi_comm(comm_), &req[q]);
  }
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    auto& b = sbuf_[q];
    b.resize(send_[q].size() * row);
    char* out = b.data();
    for (int k : fields) {
      const Field& f = p.field(k);
      const char* src = f.type == FieldType::Real ? reinterpret_cast<const char*>(f.real.data())
                                                  : reinterpret_cast<const char*>(f.ints.data());
      const std::size_t r = static_cast<std::size_t>(f.ncomp) * 8;
      for (int i : send_[q]) std::memcpy(out, src + i * r, r), out += r;
    }
    stats_.halo_bytes += static_cast<double>(b.size());
    MPI_Isend(b.data(), static_cast<int>(b.size()), MPI_BYTE, peers_[q], tag, mpi_comm(comm_),
              &req[peers_.size() + q]);
  }
  const auto tw = std::chrono::steady_clock::now();
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
  stats_.wait_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - tw).count();
  for (std::size_t q = 0; q < peers_.size(); ++q) {
    const char* in = rbuf_[q].data();
    for (int k : fields) {
      Field& f = p.field(k);
      char* dst = f.type == FieldType::Real ? reinterpret_cast<char*>(f.real.data())
                                            : reinterpret_cast<char*>(f.ints.data());
      const std::size_t r = static_cast<std::size_t>(f.ncomp) * 8;
      std::memcpy(dst + recv_first_[q] * r, in, recv_count_[q] * r);
      in += recv_count_[q] * r;
    }
  }
  stats_.exchange_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template class Decomposition<2>;
template class Decomposition<3>;

}  // namespace monosph
