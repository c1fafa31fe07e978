#pragma once
// Particles sent between ranks travel as records: every per-particle array of isph::Particles
// (for_each_array, so none is forgotten), one particle after another, as raw bytes. Shared by
// migration and the halo; not meant for use outside sph_mpi/. The arrays hold numbers and
// fixed-size Eigen vectors (plain arrays of doubles), so bytes copy them whole; the casts to
// void* say so to -Wclass-memaccess.
#include <mpi.h>

#include <cstring>
#include <type_traits>
#include <vector>

#include "mpi_collectives.hpp"
#include "particles.hpp"

namespace isph::records {

template <int Dim>
std::size_t record_bytes(Particles<Dim>& p) {
  std::size_t bytes = 0;
  p.for_each_array(
      [&](auto& a) { bytes += sizeof(typename std::decay_t<decltype(a)>::value_type); });
  return bytes;
}

// The particles order[0], order[1], ... as records.
template <int Dim>
std::vector<char> pack(Particles<Dim>& p, const std::vector<int>& order) {
  const std::size_t rec = record_bytes(p);
  std::vector<char> buf(order.size() * rec);
  std::size_t offset = 0;
  p.for_each_array([&](auto& a) {
    const std::size_t s = sizeof(typename std::decay_t<decltype(a)>::value_type);
    for (std::size_t k = 0; k < order.size(); ++k)
      std::memcpy(buf.data() + k * rec + offset, &a[order[k]], s);
    offset += s;
  });
  return buf;
}

// Every array resized to start + (the number of records), the records written from `start` on.
template <int Dim>
void unpack(const std::vector<char>& buf, Particles<Dim>& p, std::size_t start) {
  const std::size_t rec = record_bytes(p), n = rec ? buf.size() / rec : 0;
  std::size_t offset = 0;
  p.for_each_array([&](auto& a) {
    const std::size_t s = sizeof(typename std::decay_t<decltype(a)>::value_type);
    a.resize(start + n);
    for (std::size_t k = 0; k < n; ++k)
      std::memcpy(static_cast<void*>(&a[start + k]), buf.data() + k * rec + offset, s);
    offset += s;
  });
}

// Items of `item_bytes` each, send_counts[r] of them to rank r (in rank order in `send`), with
// the counts each rank receives already known: what arrives is written to `recv`, in rank order.
inline void alltoallv_into(MPI_Comm comm, const char* send, const std::vector<int>& send_counts,
                           const std::vector<int>& recv_counts, std::size_t item_bytes,
                           char* recv) {
  const int size = static_cast<int>(send_counts.size());
  std::vector<int> sd(size), rd(size);
  int s_at = 0, r_at = 0;
  for (int r = 0; r < size; ++r) {
    sd[r] = s_at;
    rd[r] = r_at;
    s_at += send_counts[r];
    r_at += recv_counts[r];
  }
  const collectives::ItemType item(item_bytes);
  MPI_Alltoallv(send, send_counts.data(), sd.data(), item.get(), recv, recv_counts.data(),
                rd.data(), item.get(), comm);
}

// As above, the receive counts exchanged first: returns what arrives and sets recv_counts.
inline std::vector<char> alltoallv(MPI_Comm comm, const std::vector<char>& send,
                                   const std::vector<int>& send_counts, std::size_t item_bytes,
                                   std::vector<int>& recv_counts) {
  const int size = static_cast<int>(send_counts.size());
  recv_counts.assign(size, 0);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm);
  std::size_t items = 0;
  for (int c : recv_counts) items += static_cast<std::size_t>(c);
  std::vector<char> recv(items * item_bytes);
  alltoallv_into(comm, send.data(), send_counts, recv_counts, item_bytes, recv.data());
  return recv;
}

}  // namespace isph::records
