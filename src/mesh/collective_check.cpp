#include "poroseam/collective_check.hpp"

namespace poroseam {

PetscErrorCode checkOnAllRanks(MPI_Comm comm, const std::string &local_error)
{
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  int mine = local_error.empty() ? size : rank, first = size;
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == size) PetscFunctionReturn(0);
  int length = rank == first ? (int)local_error.size() : 0;
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, first, comm));
  std::string message = rank == first ? local_error : std::string(length, ' ');
  PetscCallMPI(MPI_Bcast(message.data(), length, MPI_CHAR, first, comm));
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s", message.c_str());
}

} // namespace poroseam
