/* STREAM-style triad a[i] = b[i] + s c[i], run by every MPI rank at the same time (a barrier
 * before each repetition), to measure the memory bandwidth the ranks share: what a
 * bandwidth-bound code such as a sparse solve can gain from more ranks on this machine.
 *   mpiexec -n R stream_triad [doubles per array, default 10^7 = 80 MB]
 * Prints one line: ranks R, total GB/s (best repetition: all ranks' bytes over the slowest
 * rank's time), per-rank GB/s. Bytes counted as STREAM does: 3 x 8 per element (two reads,
 * one write; the write-allocate read is not counted). */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const long n = argc > 1 ? atol(argv[1]) : 10000000L;
  const int repetitions = argc > 2 ? atoi(argv[2]) : 10;
  double *a = malloc(n * sizeof(double)), *b = malloc(n * sizeof(double)),
         *c = malloc(n * sizeof(double));
  if (!a || !b || !c) {
    fprintf(stderr, "stream_triad: cannot allocate 3 x %ld doubles\n", n);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  /* Touch every page first, so the timed loops do not measure page faults. */
  for (long i = 0; i < n; ++i)
    a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
  const double s = 3.0;
  double best = 1e30;
  for (int r = 0; r < repetitions; ++r) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    for (long i = 0; i < n; ++i)
      a[i] = b[i] + s * c[i];
    double mine = MPI_Wtime() - t0, slowest;
    MPI_Allreduce(&mine, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (slowest < best) best = slowest;
  }
  /* Use the result so the compiler keeps the loop. */
  double check = 0.0, total_check;
  for (long i = 0; i < n; i += 4096)
    check += a[i];
  MPI_Reduce(&check, &total_check, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  const double bytes = 3.0 * sizeof(double) * (double)n;
  if (rank == 0)
    printf("stream_triad ranks %d array_mb %.0f best_s %.6e total_gbs %.4f per_rank_gbs %.4f "
           "check %g\n",
           size, n * sizeof(double) / 1e6, best, size * bytes / best / 1e9, bytes / best / 1e9,
           total_check);
  free(a);
  free(b);
  free(c);
  MPI_Finalize();
  return 0;
}
