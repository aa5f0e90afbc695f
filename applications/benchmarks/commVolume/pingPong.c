/* Latency and bandwidth between two MPI ranks (ping-pong): the machine
 * constants of the communication model in doc/benchmarks.md. Prints the
 * one-way time of each message size (median of the repeats), the fitted
 * latency (smallest size) and bandwidth (largest size), and the largest
 * peak resident memory of the ranks after one all-to-all (what the MPI
 * library itself holds per rank; run with more ranks to see it grow with
 * the number of peers: ranks beyond the first two only take part in the
 * all-to-all).
 *
 *   mpicc -O2 -o pingPong pingPong.c && mpirun -np 2 ./pingPong
 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int cmp(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    const int sizes[] = {8, 64, 512, 4096, 32768, 262144, 2097152, 8388608};
    const int nSizes = sizeof(sizes)/sizeof(sizes[0]);
    enum { nRepeats = 31 };
    char* buf = malloc(sizes[nSizes - 1]);
    memset(buf, 1, sizes[nSizes - 1]);
    double oneWay[sizeof(sizes)/sizeof(sizes[0])];
    for (int s = 0; s < nSizes; ++s)
    {
        const int n = sizes[s];
        const int inner = n < 65536 ? 100 : 4;
        double t[nRepeats];
        for (int r = 0; r < nRepeats; ++r)
        {
            MPI_Barrier(MPI_COMM_WORLD);
            const double t0 = MPI_Wtime();
            for (int i = 0; i < inner; ++i)
            {
                if (rank == 0)
                {
                    MPI_Send(buf, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD);
                    MPI_Recv(buf, n, MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                }
                else if (rank == 1)
                {
                    MPI_Recv(buf, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                    MPI_Send(buf, n, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
                }
            }
            t[r] = (MPI_Wtime() - t0)/(2.0*inner);
        }
        qsort(t, nRepeats, sizeof(double), cmp);
        oneWay[s] = t[nRepeats/2];
        if (rank == 0)
        {
            printf("bytes %d one-way %.3e s\n", n, oneWay[s]);
        }
    }
    {
        /* Every pair connected once, as OpenFOAM's size exchanges do */
        int nProcs = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &nProcs);
        int* sendCounts = calloc(nProcs, sizeof(int));
        int* recvCounts = calloc(nProcs, sizeof(int));
        MPI_Alltoall(sendCounts, 1, MPI_INT, recvCounts, 1, MPI_INT, MPI_COMM_WORLD);
        free(sendCounts);
        free(recvCounts);
        long peak = 0;
        char line[256];
        FILE* status = fopen("/proc/self/status", "r");
        while (status && fgets(line, sizeof(line), status))
        {
            if (strncmp(line, "VmHWM:", 6) == 0)
            {
                peak = atol(line + 6);
            }
        }
        if (status)
        {
            fclose(status);
        }
        long peakMax = 0;
        MPI_Reduce(&peak, &peakMax, 1, MPI_LONG, MPI_MAX, 0, MPI_COMM_WORLD);
        if (rank == 0)
        {
            printf("ranks %d peak memory per rank %.1f MB (largest)\n", nProcs, peakMax/1024.0);
        }
    }
    if (rank == 0)
    {
        printf("latency %.3e s\n", oneWay[0]);
        printf("bandwidth %.3e B/s\n",
               (sizes[nSizes - 1] - sizes[nSizes - 2])/(oneWay[nSizes - 1] - oneWay[nSizes - 2]));
    }
    free(buf);
    MPI_Finalize();
    return 0;
}
