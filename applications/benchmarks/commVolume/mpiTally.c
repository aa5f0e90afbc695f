/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
    MPI traffic and peak memory of each rank of a run, measured in the
    process: a PMPI shim (the MPI standard's profiling interface) loaded
    with LD_PRELOAD counts the messages and bytes each rank sends through
    the calls OpenFOAM's Pstream and FFTW's MPI transposes use (Send, Bsend,
    Ssend, Isend, Sendrecv, and the collectives Allreduce, Alltoall,
    Alltoallv, Gatherv, Scatterv: a rank's own contribution), and at MPI_Finalize appends one line per rank to the
    file named by MPI_TALLY_FILE:

        rank <r> messages <n> bytes <b> peakRSS_kB <VmHWM>
            allreduce <calls> alltoall <calls>

    (the collectives' calls separately: their cost grows with the number
    of ranks, log2(P) latencies for an all-reduce, up to P for an
    all-to-all)

    Written in C on purpose: no MPI tool in Debian reports per-rank volumes
    without a profiler installation, and the shim is 100 lines.

    With MPI_TALLY_TRACE=<bytes> each message larger than that prints a
    backtrace to stderr (where the volume comes from).

    Build: mpicc -shared -fPIC -O2 -o libmpiTally.so mpiTally.c
    Use:   mpirun -np 4 -x LD_PRELOAD=$PWD/libmpiTally.so \
               -x MPI_TALLY_FILE=tally.txt <solver> -parallel
\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <execinfo.h>

static long long tallyMessages = 0;
static long long tallyBytes = 0;
static long long tallyAllreduce = 0;
static long long tallyAlltoall = 0;

static void tally(int count, MPI_Datatype type)
{
    int size = 0;
    const char* trace = getenv("MPI_TALLY_TRACE");
    PMPI_Type_size(type, &size);
    tallyMessages += 1;
    tallyBytes += (long long)count*size;
    /* Where the large messages come from: a backtrace to stderr of every
       message above MPI_TALLY_TRACE bytes */
    if (trace && (long long)count*size > atoll(trace))
    {
        void* frames[16];
        const int n = backtrace(frames, 16);
        fprintf(stderr, "mpiTally: %lld bytes from\n", (long long)count*size);
        backtrace_symbols_fd(frames, n, 2);
    }
}

int MPI_Send(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
    tally(c, t);
    return PMPI_Send(b, c, t, d, g, m);
}

int MPI_Bsend(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
    tally(c, t);
    return PMPI_Bsend(b, c, t, d, g, m);
}

int MPI_Ssend(const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m)
{
    tally(c, t);
    return PMPI_Ssend(b, c, t, d, g, m);
}

int MPI_Isend
(
    const void* b, int c, MPI_Datatype t, int d, int g, MPI_Comm m,
    MPI_Request* r
)
{
    tally(c, t);
    return PMPI_Isend(b, c, t, d, g, m, r);
}

int MPI_Allreduce
(
    const void* s, void* r, int c, MPI_Datatype t, MPI_Op o, MPI_Comm m
)
{
    tally(c, t);
    ++tallyAllreduce;
    return PMPI_Allreduce(s, r, c, t, o, m);
}

/* Pairwise exchanges (FFTW's MPI transposes between some numbers of ranks) */
int MPI_Sendrecv
(
    const void* s, int sc, MPI_Datatype st, int d, int sg, void* r, int rc,
    MPI_Datatype rt, int src, int rg, MPI_Comm m, MPI_Status* status
)
{
    tally(sc, st);
    return PMPI_Sendrecv(s, sc, st, d, sg, r, rc, rt, src, rg, m, status);
}

int MPI_Sendrecv_replace
(
    void* b, int c, MPI_Datatype t, int d, int sg, int src, int rg,
    MPI_Comm m, MPI_Status* status
)
{
    tally(c, t);
    return PMPI_Sendrecv_replace(b, c, t, d, sg, src, rg, m, status);
}

int MPI_Alltoall
(
    const void* s, int sc, MPI_Datatype st, void* r, int rc, MPI_Datatype rt,
    MPI_Comm m
)
{
    int n = 1;
    PMPI_Comm_size(m, &n);
    tally(sc*n, st);
    ++tallyAlltoall;
    return PMPI_Alltoall(s, sc, st, r, rc, rt, m);
}

int MPI_Alltoallv
(
    const void* s, const int* sc, const int* sd, MPI_Datatype st, void* r,
    const int* rc, const int* rd, MPI_Datatype rt, MPI_Comm m
)
{
    int n = 1, i, total = 0;
    PMPI_Comm_size(m, &n);
    for (i = 0; i < n; ++i) total += sc[i];
    tally(total, st);
    ++tallyAlltoall;
    return PMPI_Alltoallv(s, sc, sd, st, r, rc, rd, rt, m);
}

int MPI_Gatherv
(
    const void* s, int sc, MPI_Datatype st, void* r, const int* rc,
    const int* rd, MPI_Datatype rt, int root, MPI_Comm m
)
{
    tally(sc, st);
    return PMPI_Gatherv(s, sc, st, r, rc, rd, rt, root, m);
}

int MPI_Scatterv
(
    const void* s, const int* sc, const int* sd, MPI_Datatype st, void* r,
    int rc, MPI_Datatype rt, int root, MPI_Comm m
)
{
    int me = 0, n = 1, i, total = 0;
    PMPI_Comm_rank(m, &me);
    if (me == root)
    {
        PMPI_Comm_size(m, &n);
        for (i = 0; i < n; ++i) total += sc[i];
        tally(total, st);
    }
    return PMPI_Scatterv(s, sc, sd, st, r, rc, rt, root, m);
}

int MPI_Finalize(void)
{
    const char* path = getenv("MPI_TALLY_FILE");
    if (path)
    {
        int rank = 0;
        long peak = -1;
        char line[256];
        FILE* status = fopen("/proc/self/status", "r");
        PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (status)
        {
            while (fgets(line, sizeof(line), status))
            {
                if (strncmp(line, "VmHWM:", 6) == 0)
                {
                    peak = atol(line + 6);
                }
            }
            fclose(status);
        }
        FILE* out = fopen(path, "a");
        if (out)
        {
            fprintf
            (
                out,
                "rank %d messages %lld bytes %lld peakRSS_kB %ld"
                " allreduce %lld alltoall %lld\n",
                rank, tallyMessages, tallyBytes, peak, tallyAllreduce,
                tallyAlltoall
            );
            fclose(out);
        }
    }
    return PMPI_Finalize();
}
