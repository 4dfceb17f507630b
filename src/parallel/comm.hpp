#pragma once
// Comm: the ranks of an Open MPI run (one rank without mpirun). Every call is collective
// unless said otherwise; with one rank they return their argument without touching MPI.
// <mpi.h> stays out of this header, which almost every file includes: the files that call MPI
// themselves get the communicator from parallel/comm_mpi.hpp.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace monosph {

class Comm {
 public:
  // MPI_Init (thread level FUNNELED) when the process was started by mpirun; a no-op otherwise,
  // so serial runs and tests never pay for MPI start-up.
  static void init(int* argc, char*** argv);
  static void finalize();
  static Comm& world();
  // Aborts every rank (an error on one rank that the others cannot see).
  [[noreturn]] static void abort(int code);

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool parallel() const { return size_ > 1; }
  bool root() const { return rank_ == 0; }
  // Global reductions and broadcasts made so far (for the communication model).
  long collectives() const { return collectives_; }
  void count_collective() const { ++collectives_; }

  double sum(double x) const;
  double min(double x) const;
  double max(double x) const;
  long sum(long x) const;
  long max(long x) const;
  long min(long x) const;
  void sum(std::span<double> x) const;  // in place, element-wise
  // As sum, then rank 0's result on every rank: the same bits everywhere, whatever the
  // reduction algorithm (state that every rank integrates alike, e.g. rigid clusters).
  void sum_same(std::span<double> x) const;
  void max(std::span<double> x) const;
  void min(std::span<double> x) const;
  void barrier() const;
  void bcast(std::string& s, int root) const;
  void bcast(std::span<double> x, int root) const;
  // The `val` of the rank with the smallest distance d2 (the lowest such rank on a tie), on all.
  void nearest(double& d2, double& val) const;
  // The message of the lowest rank whose `local` is not empty ("" if none).
  std::string first_message(const std::string& local) const;
  // send[r] goes to rank r; returns what each rank sent here, in rank order.
  std::vector<std::vector<char>> exchange(const std::vector<std::vector<char>>& send) const;

 private:
  int rank_ = 0, size_ = 1;
  mutable long collectives_ = 0;
};

}  // namespace monosph
