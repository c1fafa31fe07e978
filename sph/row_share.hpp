#pragma once
// How the rows of a step (the particles in storage order) are shared between processes. One
// process computes every row. With several (sph_mpi/block_row_share.hpp) each computes a
// contiguous block of rows, the same block as its rows of the distributed pressure equation, and
// after every stage that writes what another row's stage reads, the blocks are exchanged so that
// every process again holds every row. The solver's stages only ever loop over [first, last);
// what they leave in other rows is replaced by the exchange.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace isph {

// The first row of part p's block of n rows (p = parts: n). The AMG backend's rows are these.
inline int block_start(int n, int part, int parts) {
  return static_cast<int>(static_cast<long>(n) * part / parts);
}

class RowShare {
 public:
  virtual ~RowShare() = default;
  virtual int parts() const { return 1; }
  virtual int part() const { return 0; }
  // The rows of n this process computes.
  virtual int first(int n) const { return block_start(n, part(), parts()); }
  virtual int last(int n) const { return block_start(n, part() + 1, parts()); }
  // Each process holds only the particles it owns and a halo (sph/decomposition.hpp), not every
  // row: a pass over all rows must then reduce over the processes instead.
  virtual bool decomposed() const { return false; }

  // Every process's block of `data` (n rows of row_bytes bytes) to every process; decomposed:
  // the owners' rows into the halo's copies.
  virtual void exchange_rows(void* /*data*/, std::size_t /*row_bytes*/, int /*n*/) const {}
  // All processes' lists (of bytes), in the order of the parts.
  virtual std::vector<char> concatenate_bytes(const std::vector<char>& mine) const { return mine; }
  virtual double sum(double x) const { return x; }
  // Element-wise sum over the processes, in place.
  virtual void sum_in_place(double* /*data*/, std::size_t /*count*/) const {}
  virtual double max(double x) const { return x; }

  // The first non-empty text of all processes, in the order of the parts ("" when none has one):
  // what a stop found on some processes only, so that every process stops with the same message.
  std::string first_text(const std::string& mine) const {
    std::vector<char> bytes;
    if (!mine.empty()) bytes.assign(mine.c_str(), mine.c_str() + mine.size() + 1);
    const std::vector<char> all = concatenate_bytes(bytes);
    return all.empty() ? std::string() : std::string(all.data());
  }

  template <class T>
  void exchange(std::vector<T>& rows) const {
    if (parts() > 1) exchange_rows(rows.data(), sizeof(T), static_cast<int>(rows.size()));
  }
  // All processes' lists of trivially copyable T, in the order of the parts: with lists built
  // over each part's rows in row order, the order of one process's loop over all rows.
  template <class T>
  std::vector<T> concatenate(const std::vector<T>& mine) const {
    if (parts() == 1) return mine;
    const char* bytes = reinterpret_cast<const char*>(mine.data());
    const std::vector<char> all =
        concatenate_bytes(std::vector<char>(bytes, bytes + mine.size() * sizeof(T)));
    std::vector<T> out(all.size() / sizeof(T));
    if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), all.data(), all.size());
    return out;
  }
};

}  // namespace isph
