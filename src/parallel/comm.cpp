#include <cstdlib>
#include <stdexcept>

#include "parallel/comm_mpi.hpp"

namespace monosph {

namespace {
bool g_mpi = false;
Comm g_world;
bool started_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}
template <class T>
T reduce(const Comm& c, T x, MPI_Datatype t, MPI_Op op) {
  if (!c.parallel()) return x;
  c.count_collective();
  T y;
  MPI_Allreduce(&x, &y, 1, t, op, mpi_comm(c));
  return y;
}
void reduce(const Comm& c, std::span<double> x, MPI_Op op) {
  if (!c.parallel() || x.empty()) return;
  c.count_collective();
  MPI_Allreduce(MPI_IN_PLACE, x.data(), static_cast<int>(x.size()), MPI_DOUBLE, op, mpi_comm(c));
}
}  // namespace

MPI_Comm mpi_comm(const Comm&) {
  return g_mpi ? MPI_COMM_WORLD : MPI_COMM_NULL;
}

void Comm::init(int* argc, char*** argv) {
  if (g_mpi || !started_by_mpirun()) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  g_mpi = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_world.rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &g_world.size_);
}

void Comm::finalize() {
  if (g_mpi) MPI_Finalize();
  g_mpi = false;
}

Comm& Comm::world() {
  return g_world;
}

void Comm::abort(int code) {
  if (g_mpi) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

double Comm::sum(double x) const {
  return reduce(*this, x, MPI_DOUBLE, MPI_SUM);
}
double Comm::min(double x) const {
  return reduce(*this, x, MPI_DOUBLE, MPI_MIN);
}
double Comm::max(double x) const {
  return reduce(*this, x, MPI_DOUBLE, MPI_MAX);
}
long Comm::sum(long x) const {
  return reduce(*this, x, MPI_LONG, MPI_SUM);
}
long Comm::max(long x) const {
  return reduce(*this, x, MPI_LONG, MPI_MAX);
}
long Comm::min(long x) const {
  return reduce(*this, x, MPI_LONG, MPI_MIN);
}
void Comm::sum(std::span<double> x) const {
  reduce(*this, x, MPI_SUM);
}
void Comm::max(std::span<double> x) const {
  reduce(*this, x, MPI_MAX);
}
void Comm::min(std::span<double> x) const {
  reduce(*this, x, MPI_MIN);
}

void Comm::sum_same(std::span<double> x) const {
  reduce(*this, x, MPI_SUM);
  bcast(x, 0);
}

void Comm::barrier() const {
  if (parallel()) MPI_Barrier(mpi_comm(*this));
}

void Comm::bcast(std::string& s, int root) const {
  if (!parallel()) return;
  long n = static_cast<long>(s.size());
  ++collectives_;
  MPI_Bcast(&n, 1, MPI_LONG, root, mpi_comm(*this));
  s.resize(n);
  if (n) MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, mpi_comm(*this));
}

void Comm::bcast(std::span<double> x, int root) const {
  if (parallel() && !x.empty())
    MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_DOUBLE, root, mpi_comm(*this));
}

void Comm::nearest(double& d2, double& val) const {
  if (!parallel()) return;
  const double best = min(d2);
  const long who = min(d2 == best ? long(rank_) : long(size_));
  bcast(std::span<double>(&val, 1), static_cast<int>(who));
  d2 = best;
}

std::string Comm::first_message(const std::string& local) const {
  if (!parallel()) return local;
  const long who = min(local.empty() ? long(size_) : long(rank_));
  if (who == size_) return "";
  std::string s = local;
  bcast(s, static_cast<int>(who));
  return s;
}

std::vector<std::vector<char>> Comm::exchange(const std::vector<std::vector<char>>& send) const {
  if (!parallel()) return {send.at(0)};
  std::vector<long> scount(size_), rcount(size_);
  for (int r = 0; r < size_; ++r) scount[r] = static_cast<long>(send[r].size());
  MPI_Alltoall(scount.data(), 1, MPI_LONG, rcount.data(), 1, MPI_LONG, mpi_comm(*this));
  std::vector<std::vector<char>> recv(size_);
  std::vector<MPI_Request> req;
  req.reserve(2 * size_);
  constexpr int tag = 17;
  for (int r = 0; r < size_; ++r) {
    recv[r].resize(rcount[r]);
    if (rcount[r] == 0) continue;
    if (rcount[r] > (1L << 31) - 1) throw std::runtime_error("MPI message above 2 GiB");
    req.emplace_back();
    MPI_Irecv(recv[r].data(), static_cast<int>(rcount[r]), MPI_BYTE, r, tag, mpi_comm(*this),
              &req.back());
  }
  for (int r = 0; r < size_; ++r) {
    if (scount[r] == 0) continue;
    req.emplace_back();
    MPI_Isend(send[r].data(), static_cast<int>(scount[r]), MPI_BYTE, r, tag, mpi_comm(*this),
              &req.back());
  }
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
  return recv;
}

}  // namespace monosph
