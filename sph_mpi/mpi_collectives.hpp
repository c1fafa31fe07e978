#pragma once
// The reductions and the concatenation both RowShare implementations of sph_mpi/ offer, and the
// item type their exchanges count in.
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace isph::collectives {

// Every process's bytes, in the order of the ranks, to every process.
std::vector<char> concatenate(MPI_Comm comm, const std::vector<char>& mine);
double sum(MPI_Comm comm, double x);
void sum_in_place(MPI_Comm comm, double* data, std::size_t count);
double max(MPI_Comm comm, double x);

// `bytes` contiguous bytes as one MPI datatype, so that an exchange counts items: counted in
// bytes, a rank's share beyond 2 GiB (some ten million particle records in 3D) overflows MPI's
// int counts and displacements.
class ItemType {
 public:
  explicit ItemType(std::size_t bytes) {
    MPI_Type_contiguous(static_cast<int>(bytes), MPI_BYTE, &type_);
    MPI_Type_commit(&type_);
  }
  ~ItemType() { MPI_Type_free(&type_); }
  ItemType(const ItemType&) = delete;
  ItemType& operator=(const ItemType&) = delete;
  MPI_Datatype get() const { return type_; }

 private:
  MPI_Datatype type_;
};

}  // namespace isph::collectives
